#include "nodes/screen_space_reference.h"

#include <algorithm>
#include <cmath>

#include "nodes/eval_math.h"
#include "nodes/shading_reference.h"

namespace wg::nodes {
namespace {

using glsl::clamp;

Value v3(double x, double y, double z) { return Value::vector({x, y, z}); }
// Column-major mat4 times a vec4: m[col][row] = c[col * 4 + row].
void mulMat4(const Value& m, const double in[4], double out[4]) {
  for (int r = 0; r < 4; ++r) {
    out[r] = 0;
    for (int c = 0; c < 4; ++c) out[r] += m[c * 4 + r] * in[c];
  }
}
double max3(const Value& c) { return std::max(c[0], std::max(c[1], c[2])); }
double distance3(const Value& a, const Value& b) {
  double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

}  // namespace

Value sceneDepthPositionReference(const Value& uv, double lin, const Value& camera, const Value& view,
                                  const Value& proj) {
  double nx = uv[0] * 2.0 - 1.0, ny = uv[1] * 2.0 - 1.0;
  double px = std::fabs(proj[0]) < 1e-6 ? 1e-6 : proj[0];
  double py = std::fabs(proj[5]) < 1e-6 ? 1e-6 : proj[5];
  double ray[3] = {(nx + proj[8]) / px, (ny + proj[9]) / py, -1.0};
  Value out = Value::ofType(Type::Vec3);
  for (int j = 0; j < 3; ++j) {
    // transpose(mat3(view)) * ray: component j is column j of mat3(view) dotted with ray.
    double w = view[4 * j] * ray[0] + view[4 * j + 1] * ray[1] + view[4 * j + 2] * ray[2];
    out[j] = clamp(camera[j] + w * lin, -1e30, 1e30);
  }
  return out;
}

Value sceneColorUvReference(const Value& uv, const Value& offset) {
  return Value::vector({clamp(uv[0] + offset[0], 0.0, 1.0), clamp(uv[1] + offset[1], 0.0, 1.0)});
}

SsrMarch ssrMarchReference(double sceneDepth, const Value& origin, const Value& dir, double cosRn, const Value& view,
                           const Value& proj, const Value& nearFar, int steps, double stepLength, double tolerance,
                           double growth) {
  return ssrMarchReference([sceneDepth](double, double) { return sceneDepth; }, origin, dir, cosRn, view, proj, nearFar,
                           steps, stepLength, tolerance, growth);
}

SsrMarch ssrMarchReference(const SceneDepthAt& depthAt, const Value& origin, const Value& dir, double cosRn,
                           const Value& view, const Value& proj, const Value& nearFar, int steps, double stepLength,
                           double tolerance, double growth) {
  double stride = std::max(stepLength, 1e-4) / std::max(0.6, cosRn * cosRn);
  double t = 0.5 * stride;
  double tol2 = tolerance * tolerance;
  double g = std::max(growth, 0.0);
  SsrMarch m;
  for (int i = 0; i < steps; ++i) {
    m.steps = i + 1;
    double p[4] = {origin[0] + t * dir[0], origin[1] + t * dir[1], origin[2] + t * dir[2], 1.0};
    double vp[4], clip[4];
    mulMat4(view, p, vp);
    t += stride;
    mulMat4(proj, vp, clip);
    if (clip[3] <= 1e-6) break;
    double u = clip[0] / clip[3] * 0.5 + 0.5, v = clip[1] / clip[3] * 0.5 + 0.5;
    if (u < 0.0 || u > 1.0 || v < 0.0 || v > 1.0) break;
    double diff = -vp[2] - linearizeDepthReference(depthAt(u, v), nearFar[0], nearFar[1]);
    if (diff * diff < tol2) {
      m.u = u, m.v = v, m.hit = true;
      return m;
    }
    tol2 *= g;
  }
  return m;
}

double ssrFadeReference(double u, double v, double dist, double fadeDistance) {
  double dx = u * 2.0 - 1.0, dy = v * 2.0 - 1.0;
  double edge = std::max(1.0 - std::sqrt(std::sqrt(0.01 + dx * dx + dy * dy)), 0.0);
  return edge * std::min(1.0, std::max(fadeDistance, 0.0) / std::max(dist, 1e-6));
}

UnderwaterResult underwaterFromAboveReference(const UnderwaterInputs& in) {
  bool covered = in.water[3] < 1.0;
  double height = covered ? in.water[1] : in.level;
  if (!covered || height - in.scene[1] <= 0.0) return {in.sceneColorAt(in.uv[0], in.uv[1]), 1};
  double dw = distance3(in.water, in.camera);
  double ds = in.sky > 0.5 ? 1e30 : distance3(in.scene, in.camera);
  Value t = beerLambertReference(in.sigma, std::max(ds - dw, 0.0));
  Value body = v3(in.waterColor[0] * in.diffuse, in.waterColor[1] * in.diffuse, in.waterColor[2] * in.diffuse);
  int which = 5;
  if (max3(t) > 0.00390625 && ds < in.hazeDistance) {
    Value offset = Value::vector({in.strength * (1.0 - t[2]) * in.normal[0], in.strength * (1.0 - t[2]) * in.normal[2]});
    Value ruv = sceneColorUvReference(in.uv, offset);
    Value refr = in.sceneColorAt(ruv[0], ruv[1]);
    double c = in.caustics * max3(refr);
    for (int i = 0; i < 3; ++i)
      body[i] = t[i] * (refr[i] + in.causticsColor[i] * c) + (1.0 - t[i]) * in.waterColor[i] * in.diffuse;
    which = 4;
  }
  double h = hazeFactorReference(dw, in.hazeDistance);
  Value out = Value::ofType(Type::Vec3);
  for (int i = 0; i < 3; ++i) out[i] = glsl::mix(in.transmittance * body[i] + in.surface[i], in.hazeColor[i], h);
  return {out, which};
}

UnderwaterResult underwaterFromBelowReference(const UnderwaterInputs& in) {
  bool covered = in.water[3] < 1.0;
  double height = covered ? in.water[1] : in.level;
  double k = std::min(1.0, std::max(in.depthLight, 0.0) / std::max(in.level - in.camera[1], 1e-6));
  Value out = Value::ofType(Type::Vec3);
  if (!covered || height - in.scene[1] > 0.0) {
    Value col = in.sceneColorAt(in.uv[0], in.uv[1]);
    double ds = in.sky > 0.5 ? 1e30 : distance3(in.scene, in.camera);
    Value t = beerLambertReference(in.sigma, ds);
    double c = in.caustics * max3(col);
    for (int i = 0; i < 3; ++i)
      out[i] = k * (t[i] * (col[i] + in.causticsColor[i] * c) + (1.0 - t[i]) * in.waterColor[i] * in.diffuse);
    return {out, 2};
  }
  Value t = beerLambertReference(in.sigma, distance3(in.water, in.camera));
  Value suv = sceneColorUvReference(in.uv, Value::vector({in.strength * in.normal[0], in.strength * in.normal[2]}));
  Value seen = in.sceneColorAt(suv[0], suv[1]);
  for (int i = 0; i < 3; ++i)
    out[i] = k * (t[i] * (in.transmittance * seen[i] + in.surface[i]) + (1.0 - t[i]) * in.waterColor[i] * in.diffuse);
  return {out, 3};
}

}  // namespace wg::nodes
