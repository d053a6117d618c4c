// The built-in scene's floating buoys (runtime/floating_buoys.h).
#include "runtime/floating_buoys.h"

#include <cmath>
#include <limits>
#include <utility>

#include "codegen/water_surface_eval.h"
#include "nodes/texture_source.h"
#include "runtime/uniform_values.h"

namespace wg::rt {
namespace {

constexpr double kNormalStep = 0.05;  // metres between the central differences' points
constexpr int kBuoySegments = 16;
// A small navigation buoy, local y up, the water line at y = 0.
constexpr float kBuoyRadius = 0.35f, kBuoyDraft = 0.4f, kBodyTop = 0.35f, kTopTip = 0.9f, kTipRadius = 0.05f;
constexpr float kBodyMaterial = 3.0f, kTopMaterial = 4.0f;

glm::dvec3 displaced(const wg::Program& program, const std::vector<Value>& parameters, double x0, double z0, double t,
                     TextureCache& textures) {
  const WaterSurfacePoint p = waterSurfaceAt(program, parameters, x0, z0, t, &textures);
  return {p.position[0], p.position[1], p.position[2]};
}

// A unit up axis from `n`, or straight up where `n` is degenerate or not finite.
glm::vec3 upFrom(const glm::dvec3& n) {
  const double len = glm::length(n);
  if (!(len > 1e-12) || !std::isfinite(len)) return {0.0f, 1.0f, 0.0f};
  glm::dvec3 u = n / len;
  if (u.y < 0) u = -u;  // a buoy floats upright even where a fold turns the sheet over
  return glm::vec3(u);
}

// Adds one ring band of the buoy: radius r0 at y0 to r1 at y1, outward normals.
void addBand(Mesh& m, const glm::mat3& axes, const glm::vec3& origin, float r0, float y0, float r1, float y1, float material) {
  const unsigned base = static_cast<unsigned>(m.vertexCount());
  const float slope = (r0 - r1) / (y1 - y0);  // the cone's normal leans up by its taper
  for (int i = 0; i <= kBuoySegments; ++i) {
    const float a = 6.2831853f * static_cast<float>(i) / kBuoySegments;
    const glm::vec3 radial(std::cos(a), 0.0f, std::sin(a));
    const glm::vec3 normal = axes * glm::normalize(radial + glm::vec3(0.0f, slope, 0.0f));
    for (auto [r, y] : {std::pair{r0, y0}, std::pair{r1, y1}}) {
      const glm::vec3 p = origin + axes * glm::vec3(radial.x * r, y, radial.z * r);
      m.vertices.insert(m.vertices.end(), {p.x, p.y, p.z, normal.x, normal.y, normal.z, material});
    }
  }
  for (unsigned i = 0; i < kBuoySegments; ++i) {
    const unsigned a = base + 2 * i, b = a + 1, c = a + 2, d = a + 3;
    m.indices.insert(m.indices.end(), {a, b, c, c, b, d});
  }
}

// The bottom disc, facing down.
void addBottom(Mesh& m, const glm::mat3& axes, const glm::vec3& origin) {
  const unsigned centre = static_cast<unsigned>(m.vertexCount());
  const glm::vec3 down = axes * glm::vec3(0.0f, -1.0f, 0.0f), c = origin + axes * glm::vec3(0.0f, -kBuoyDraft, 0.0f);
  m.vertices.insert(m.vertices.end(), {c.x, c.y, c.z, down.x, down.y, down.z, kBodyMaterial});
  for (int i = 0; i <= kBuoySegments; ++i) {
    const float a = 6.2831853f * static_cast<float>(i) / kBuoySegments;
    const glm::vec3 p = origin + axes * glm::vec3(kBuoyRadius * std::cos(a), -kBuoyDraft, kBuoyRadius * std::sin(a));
    m.vertices.insert(m.vertices.end(), {p.x, p.y, p.z, down.x, down.y, down.z, kBodyMaterial});
  }
  for (unsigned i = 0; i < kBuoySegments; ++i) m.indices.insert(m.indices.end(), {centre, centre + 2 + i, centre + 1 + i});
}

}  // namespace

const std::vector<glm::dvec2>& buoyRestPoints() {
  static const std::vector<glm::dvec2> points = {{4.0, 1.5}, {-3.0, 3.5}, {9.5, -6.5}};
  return points;
}

std::vector<FloatingPose> floatingBuoys(const wg::Program& program, const std::vector<Value>& given, double time) {
  // Each value clamped into its range as the renderer clamps the uniform it uploads, so the
  // buoys ride the water the frame shows.
  std::vector<Value> parameters = given;
  const double unbounded = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < parameters.size() && i < program.parameters.size(); ++i) {
    const ProgramParameter& p = program.parameters[i];
    for (int k = 0; k < parameters[i].size(); ++k)
      parameters[i][k] = clampedIntoRange(parameters[i][k], p.min.value_or(-unbounded), p.max.value_or(unbounded));
  }
  std::vector<FloatingPose> poses;
  TextureCache textures;  // a vertex stage's node textures, read once for every point
  for (const glm::dvec2& rest : buoyRestPoints()) {
    const glm::dvec3 at = displaced(program, parameters, rest.x, rest.y, time, textures);
    // The displaced sheet's tangents along x0 and z0; their cross product is its normal, the
    // surface queries' normal (which differentiates exactly) within the differences' error.
    const double h = kNormalStep;
    const glm::dvec3 alongX = displaced(program, parameters, rest.x + h, rest.y, time, textures) -
                              displaced(program, parameters, rest.x - h, rest.y, time, textures);
    const glm::dvec3 alongZ = displaced(program, parameters, rest.x, rest.y + h, time, textures) -
                              displaced(program, parameters, rest.x, rest.y - h, time, textures);
    const glm::dvec3 normal = glm::cross(alongZ, alongX);
    FloatingPose pose;
    pose.position = glm::vec3(at);
    pose.up = upFrom(normal);
    poses.push_back(pose);
  }
  return poses;
}

Mesh buoyMesh(const std::vector<FloatingPose>& poses) {
  Mesh m;
  m.floatsPerVertex = 7;
  for (const FloatingPose& pose : poses) {
    // Axes: the up axis, and x and z turned with it (the heading stays fixed).
    const glm::vec3 up = pose.up;
    glm::vec3 forward = glm::cross(glm::vec3(1.0f, 0.0f, 0.0f), up);
    forward = glm::length(forward) > 1e-6f ? glm::normalize(forward) : glm::vec3(0.0f, 0.0f, 1.0f);
    const glm::vec3 right = glm::cross(up, forward);
    const glm::mat3 axes(right, up, forward);
    addBand(m, axes, pose.position, kBuoyRadius, -kBuoyDraft, kBuoyRadius, kBodyTop, kBodyMaterial);
    addBand(m, axes, pose.position, kBuoyRadius, kBodyTop, kTipRadius, kTopTip, kTopMaterial);
    addBottom(m, axes, pose.position);
  }
  return m;
}

}  // namespace wg::rt
