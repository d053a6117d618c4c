#include "runtime/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/gtc/matrix_transform.hpp>

namespace wg::rt {
namespace {

constexpr float kPi = 3.14159265358979f;

struct Preset {
  const char* name;
  Camera camera;
};

const std::vector<Preset>& presets() {
  static const std::vector<Preset> p = {
      // Over the deep end, looking across the pillars and rocks towards the shore.
      {"above", {{14.0f, 7.0f, -12.0f}, {-4.0f, -1.5f, 4.0f}, 55.0f, 0.1f, 200.0f}},
      // Half a metre above the water, looking along -x at the shore: Fresnel at grazing.
      {"grazing", {{17.0f, 0.5f, -3.0f}, {-10.0f, 0.2f, 3.0f}, 50.0f, 0.1f, 200.0f}},
      // Below the surface, looking slightly up: the water seen from below.
      {"underwater", {{10.0f, -1.8f, -8.0f}, {-6.0f, -0.6f, 4.0f}, 65.0f, 0.1f, 200.0f}},
      // Straight down over the middle; +x to the right, +z down the image.
      {"topdown", {{0.0f, 38.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, 60.0f, 0.1f, 200.0f}},
  };
  return p;
}

// Deterministic hash in [0, 1) (integer arithmetic; no platform rand).
float hash01(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return static_cast<float>(x >> 8) / 16777216.0f;
}

void pushVertex(Mesh& m, glm::vec3 p, glm::vec3 n, float material) {
  m.vertices.insert(m.vertices.end(), {p.x, p.y, p.z, n.x, n.y, n.z, material});
}

void addTerrain(Mesh& m) {
  constexpr float kHalf = 40.0f;
  constexpr int kQuads = 80;
  auto base = static_cast<unsigned>(m.vertexCount());
  const float step = 2 * kHalf / kQuads;
  for (int j = 0; j <= kQuads; ++j)
    for (int i = 0; i <= kQuads; ++i) {
      float x = -kHalf + i * step, z = -kHalf + j * step;
      float e = 0.05f;
      glm::vec3 n = glm::normalize(glm::vec3(terrainHeight(x - e, z) - terrainHeight(x + e, z), 2 * e,
                                             terrainHeight(x, z - e) - terrainHeight(x, z + e)));
      pushVertex(m, {x, terrainHeight(x, z), z}, n, 0.0f);
    }
  for (int j = 0; j < kQuads; ++j)
    for (int i = 0; i < kQuads; ++i) {
      unsigned a = base + static_cast<unsigned>(j * (kQuads + 1) + i), b = a + 1, c = a + kQuads + 1, d = c + 1;
      m.indices.insert(m.indices.end(), {a, c, b, b, c, d});
    }
}

void addPillar(Mesh& m, glm::vec2 centre, float radius, float bottom, float top) {
  constexpr int kSegments = 20;
  auto base = static_cast<unsigned>(m.vertexCount());
  for (int s = 0; s <= kSegments; ++s) {
    float a = 2 * kPi * s / kSegments;
    glm::vec3 n(std::cos(a), 0.0f, std::sin(a));
    pushVertex(m, {centre.x + radius * n.x, bottom, centre.y + radius * n.z}, n, 1.0f);
    pushVertex(m, {centre.x + radius * n.x, top, centre.y + radius * n.z}, n, 1.0f);
  }
  for (unsigned s = 0; s < kSegments; ++s) {
    unsigned a = base + 2 * s, b = a + 1, c = a + 2, d = a + 3;
    m.indices.insert(m.indices.end(), {a, b, c, c, b, d});
  }
  // Top cap.
  unsigned centreIndex = static_cast<unsigned>(m.vertexCount());
  pushVertex(m, {centre.x, top, centre.y}, {0, 1, 0}, 1.0f);
  for (int s = 0; s <= kSegments; ++s) {
    float a = 2 * kPi * s / kSegments;
    pushVertex(m, {centre.x + radius * std::cos(a), top, centre.y + radius * std::sin(a)}, {0, 1, 0}, 1.0f);
  }
  for (unsigned s = 0; s < kSegments; ++s)
    m.indices.insert(m.indices.end(), {centreIndex, centreIndex + 2 + s, centreIndex + 1 + s});
}

// A lumpy, flattened sphere: the radius varies smoothly with phases from a deterministic
// hash, so the silhouette is irregular but identical on every run.
void addRock(Mesh& m, glm::vec3 centre, float radius, float flatten, uint32_t seed) {
  constexpr int kLon = 24, kLat = 12;
  auto base = static_cast<unsigned>(m.vertexCount());
  // Smooth lumps: a few low-frequency waves over the sphere with hashed phases.
  float ph[4];
  for (int k = 0; k < 4; ++k) ph[k] = 2 * kPi * hash01(seed * 9781u + static_cast<uint32_t>(k));
  auto bump = [&](int i, int j) {
    float lon = 2 * kPi * i / kLon, lat = kPi * j / kLat - kPi / 2;
    return 1.0f + 0.12f * std::sin(3 * lon + ph[0]) * std::cos(2 * lat + ph[1]) +
           0.07f * std::sin(5 * lon + ph[2]) * std::cos(lat) + 0.05f * std::sin(4 * lat + ph[3]);
  };
  auto pointAt = [&](int i, int j) {
    float lon = 2 * kPi * i / kLon, lat = kPi * j / kLat - kPi / 2;
    glm::vec3 d(std::cos(lat) * std::cos(lon), std::sin(lat), std::cos(lat) * std::sin(lon));
    float r = radius * bump(i, j);
    return centre + glm::vec3(d.x * r, d.y * r * flatten, d.z * r);
  };
  for (int j = 0; j <= kLat; ++j)
    for (int i = 0; i <= kLon; ++i) {
      glm::vec3 p = pointAt(i, j);
      // Normal from the neighbouring points (finite differences on the surface).
      glm::vec3 du = pointAt(i + 1, j) - pointAt(i > 0 ? i - 1 : kLon - 1, j);
      glm::vec3 dv = pointAt(i, std::min(j + 1, kLat)) - pointAt(i, std::max(j - 1, 0));
      glm::vec3 n = glm::cross(dv, du);
      float len = glm::length(n);
      n = len > 1e-6f ? n / len : glm::normalize(p - centre);
      if (glm::dot(n, p - centre) < 0) n = -n;
      pushVertex(m, p, n, 2.0f);
    }
  for (int j = 0; j < kLat; ++j)
    for (int i = 0; i < kLon; ++i) {
      unsigned a = base + static_cast<unsigned>(j * (kLon + 1) + i), b = a + 1, c = a + kLon + 1, d = c + 1;
      m.indices.insert(m.indices.end(), {a, c, b, b, c, d});
    }
}

}  // namespace

glm::vec3 Camera::up() const {
  glm::vec3 dir = glm::normalize(target - position);
  return std::abs(dir.y) > 0.99f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
}

glm::mat4 Camera::view() const { return glm::lookAt(position, target, up()); }

glm::mat4 Camera::projection(float aspect) const {
  return glm::perspective(glm::radians(fovYDegrees), aspect, nearPlane, farPlane);
}

const std::vector<std::string>& cameraPresetNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& p : presets()) n.push_back(p.name);
    return n;
  }();
  return names;
}

std::optional<Camera> cameraPreset(std::string_view name) {
  for (const auto& p : presets())
    if (name == p.name) return p.camera;
  return std::nullopt;
}

glm::vec3 sunDirection(const SceneOptions& o) {
  float az = glm::radians(o.sunAzimuthDegrees), el = glm::radians(o.sunElevationDegrees);
  return glm::normalize(glm::vec3(std::cos(el) * std::cos(az), std::sin(el), std::cos(el) * std::sin(az)));
}

float terrainHeight(float x, float z) {
  constexpr float kFloor = -3.5f, kTop = 1.2f;
  // Shore: flat pool floor down to x = -1, then a straight slope towards -x reaching the
  // water line at x ~ -11.4 and the top at x = -15, with faint sand ripples on the slope.
  float t = std::clamp((-x - 1.0f) / 14.0f, 0.0f, 1.0f);
  float shore = kFloor + (kTop - kFloor) * t + 0.04f * std::sin(2.1f * z + 0.7f * x) * t * (1 - t) * 4;
  // Pool walls at z = +-20 and x = +20 (steep smoothstep up to the rim).
  float r = std::max(std::abs(z), x);
  float s = std::clamp((r - 19.0f) / 1.5f, 0.0f, 1.0f);
  float wall = kFloor + (kTop + 0.3f - kFloor) * s * s * (3 - 2 * s);
  return std::max(shore, wall);
}

Mesh buildSceneMesh() {
  Mesh m;
  m.floatsPerVertex = 7;
  addTerrain(m);
  addPillar(m, {6.0f, -5.0f}, 0.6f, -4.0f, 3.0f);
  addPillar(m, {2.5f, 6.5f}, 0.5f, -4.0f, 2.2f);
  addPillar(m, {-5.0f, -8.0f}, 0.7f, -4.0f, 3.6f);
  addPillar(m, {-7.5f, 5.0f}, 0.45f, -4.0f, 1.6f);
  addRock(m, {9.0f, -0.6f, 3.0f}, 1.8f, 0.7f, 1);
  addRock(m, {-1.5f, -0.5f, -2.5f}, 1.3f, 0.8f, 2);
  addRock(m, {-10.5f, 0.0f, -4.0f}, 1.5f, 0.6f, 3);
  addRock(m, {13.0f, -3.0f, -10.0f}, 1.2f, 0.7f, 4);  // fully under water
  return m;
}

const std::vector<EnvironmentFace>& environmentFaces() {
  static const std::vector<EnvironmentFace> faces = {
      {{1, 0, 0}, {0, -1, 0}}, {{-1, 0, 0}, {0, -1, 0}}, {{0, 1, 0}, {0, 0, 1}},
      {{0, -1, 0}, {0, 0, -1}}, {{0, 0, 1}, {0, -1, 0}}, {{0, 0, -1}, {0, -1, 0}},
  };
  return faces;
}

Mesh buildWaterGrid(int quadsPerSide) {
  Mesh m;
  m.floatsPerVertex = 8;  // position, normal, uv
  int n = std::max(quadsPerSide, 1);
  m.vertices.reserve(static_cast<size_t>((n + 1) * (n + 1) * 8));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      float u = static_cast<float>(i) / n, v = static_cast<float>(j) / n;
      float x = -kWaterHalfSize + 2 * kWaterHalfSize * u, z = -kWaterHalfSize + 2 * kWaterHalfSize * v;
      m.vertices.insert(m.vertices.end(), {x, 0.0f, z, 0.0f, 1.0f, 0.0f, u, v});
    }
  m.indices.reserve(static_cast<size_t>(n * n * 6));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      unsigned a = static_cast<unsigned>(j * (n + 1) + i), b = a + 1, c = a + static_cast<unsigned>(n) + 1, d = c + 1;
      m.indices.insert(m.indices.end(), {a, c, b, b, c, d});
    }
  return m;
}

}  // namespace wg::rt
