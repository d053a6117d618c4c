#include "nodes/shading_reference.h"

#include <algorithm>
#include <cmath>

#include "nodes/eval_math.h"
#include "nodes/fresnel_reference.h"

namespace wg::nodes {
namespace {

using glsl::clamp;
using glsl::dot;
using glsl::safeNormalize;

Value vec3(double x, double y, double z) { return Value::vector({x, y, z}); }
Value add(const Value& a, const Value& b) { return vec3(a[0] + b[0], a[1] + b[1], a[2] + b[2]); }
Value sub(const Value& a, const Value& b) { return vec3(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }
Value mul(const Value& a, double k) { return vec3(a[0] * k, a[1] * k, a[2] * k); }
// GLSL mix of two vec3 by a scalar.
Value mixv(const Value& a, const Value& b, double t) {
  return vec3(glsl::mix(a[0], b[0], t), glsl::mix(a[1], b[1], t), glsl::mix(a[2], b[2], t));
}

}  // namespace

Value reflectDirReference(const Value& n, const Value& v) {
  Value nn = safeNormalize(n), vv = safeNormalize(v);
  Value i = mul(vv, -1.0);
  // reflect(I, N) = I - 2 dot(N, I) N
  return safeNormalize(sub(i, mul(nn, 2.0 * dot(nn, i))));
}

Refraction refractDirReference(const Value& n, const Value& v, double eta) {
  Value nn = safeNormalize(n), vv = safeNormalize(v);
  double c = clamp(dot(nn, vv), 0.0, 1.0);
  double k = 1.0 - eta * eta * (1.0 - c * c);
  if (k < 0.0) return {safeNormalize(sub(mul(nn, 2.0 * c), vv)), true};
  return {safeNormalize(add(mul(vv, -eta), mul(nn, eta * c - std::sqrt(k)))), false};
}

double lambertReference(const Value& n, const Value& l) {
  return clamp(dot(safeNormalize(n), safeNormalize(l)), 0.0, 1.0);
}

double blinnPhongSpecularReference(const Value& n, const Value& v, const Value& l, double shininess) {
  Value h = safeNormalize(add(safeNormalize(l), safeNormalize(v)));
  double ndoth = clamp(dot(safeNormalize(n), h), 0.0, 1.0);
  return glsl::safePow(ndoth, shininess);
}

double phongSpecularLobeReference(const Value& n, const Value& v, const Value& l) {
  Value nn = safeNormalize(n), ll = safeNormalize(l);
  Value r = sub(mul(nn, 2.0 * dot(nn, ll)), ll);
  return clamp(dot(r, safeNormalize(v)), 0.0, 1.0);
}

double ggxDistributionReference(double ndoth, double a2) {
  double c2 = ndoth * ndoth;
  double d = c2 * a2 + (1.0 - c2);
  return a2 / (3.14159265358979 * d * d);
}

double ggxVisibilityReference(double ndotl, double ndotv, double roughness) {
  double r = roughness + 1.0;
  double k = r * r / 8.0;
  return 1.0 / (4.0 * (ndotl * (1.0 - k) + k) * (ndotv * (1.0 - k) + k));
}

GgxTerms ggxSpecularReference(const Value& n, const Value& v, const Value& l, double roughness, double f0) {
  Value nn = safeNormalize(n), vv = safeNormalize(v), ll = safeNormalize(l);
  Value h = safeNormalize(add(ll, vv));
  double rough = clamp(roughness, 0.001, 1.0);
  double a = rough * rough;
  GgxTerms t;
  t.ndotl = clamp(dot(nn, ll), 0.0, 1.0);
  double ndotv = clamp(dot(nn, vv), 0.0, 1.0);
  double ndoth = clamp(dot(nn, h), 0.0, 1.0);
  double vdoth = clamp(dot(vv, h), 0.0, 1.0);
  t.d = ggxDistributionReference(ndoth, a * a);
  t.f = fresnelSchlick(vdoth, f0);
  t.brdf = t.d * t.f * ggxVisibilityReference(t.ndotl, ndotv, rough);
  return t;
}

double ggxBeckmannReference(double ndoth, double a2) {
  const double c2 = ndoth * ndoth;
  const double x = (1.0 - c2) / (c2 * a2);
  if (!(x <= 80.0)) return 0.0;  // as the GLSL: below e^-80 of the lobe's scale
  return std::exp(-x) / (3.14159265358979 * a2 * c2 * c2);
}

GgxTerms ggxSpecularFilteredReference(const Value& n, const Value& v, const Value& l, double roughness,
                                      double variance, double f0) {
  const double spread = std::min(variance, 1e4);
  if (!(spread > 0.0)) return ggxSpecularReference(n, v, l, roughness, f0);
  Value nn = safeNormalize(n), vv = safeNormalize(v), ll = safeNormalize(l);
  Value h = safeNormalize(add(ll, vv));
  const double rough = clamp(roughness, 0.001, 1.0);
  const double a = rough * rough, a2 = a * a;
  const double wide = a2 + spread, w = a2 / wide;
  const double ndoth = clamp(dot(nn, h), 0.0, 1.0);
  GgxTerms t;
  t.d = w * ggxDistributionReference(ndoth, wide) + (1.0 - w) * ggxBeckmannReference(ndoth, wide);
  // The reflecting facets' normal, between N and H by the variances' ratio.
  Value facet = safeNormalize(add(mul(nn, w * ndoth), mul(h, 1.0 - w)));
  t.ndotl = clamp(dot(facet, ll), 0.0, 1.0);
  const double fdotv = clamp(dot(facet, vv), 0.0, 1.0);
  const double fdoth = clamp(dot(facet, h), 0.0, 1.0);
  const double area = fdoth > 0.0 ? ndoth / fdoth : 0.0;
  t.f = fresnelSchlick(clamp(dot(vv, h), 0.0, 1.0), f0);
  t.brdf = t.d * area * t.f * ggxVisibilityReference(t.ndotl, fdotv, rough);
  return t;
}

NearFarRatio nearFarRatioReference(double nearPlane, double farPlane) {
  double n = std::max(nearPlane, 1e-6);
  return {n, n / std::max(farPlane, n)};
}

double linearizeDepthReference(double depth, double nearPlane, double farPlane) {
  NearFarRatio nr = nearFarRatioReference(nearPlane, farPlane);
  return linearizeDepthRatioReference(depth, nr.nearPlane, nr.ratio);
}

double linearizeDepthRatioReference(double depth, double n, double r) {
  double d = clamp(depth, 0.0, 1.0);
  double denom = (1.0 - d) + d * r;
  return std::min(n / std::max(denom, n * 1e-30), kMaxLinearDepth);
}

double waterDepthRayFactorReference(const Value& view, const Value& v) {
  // Column-major: view[col][row] = c[col * 4 + row]; row 2 of the rotation.
  Value fwd = vec3(-view[2], -view[6], -view[10]);
  if (dot(fwd, fwd) < 0.5) return 1.0;
  double c = dot(mul(safeNormalize(v), -1.0), safeNormalize(fwd));
  return 1.0 / std::max(c, 0.1);
}

double waterDepthRayFactorAxisReference(const Value& axis, const Value& v) {
  if (dot(axis, axis) < 0.25) return 1.0;
  double c = dot(mul(safeNormalize(v), -1.0), axis);
  return 1.0 / std::max(c, 0.1);
}

double waterDepthThicknessReference(double sceneLinear, double surfaceLinear, double factor, double vertical) {
  return std::min(std::max(sceneLinear - surfaceLinear, 0.0) * factor * vertical, 1e30);
}

Value beerLambertReference(const Value& sigma, double distance) {
  double d = clamp(distance, 0.0, 1e30);
  return vec3(std::exp(-std::max(sigma[0], 0.0) * d), std::exp(-std::max(sigma[1], 0.0) * d),
              std::exp(-std::max(sigma[2], 0.0) * d));
}

Value relativeAbsorptionReference(double distance, double maxDistance, double kRed, double kGreen) {
  double d = clamp(distance, 0.0, 1e30);
  double m = std::max(maxDistance, 1e-6);
  double b = clamp((m - d) / m, 0.0, 1.0);
  double g = clamp(b * (1.0 - d * kGreen), 0.0, 1.0);
  double r = clamp(b * (1.0 - d * kRed), 0.0, 1.0);
  return vec3(r * r, g * g, b * b);
}

double hazeFactorReference(double distance, double hazeDistance) {
  return clamp(distance / std::max(hazeDistance, 1e-6), 0.0, 1.0);
}

uint32_t colorVariationPcg(uint32_t v) {
  uint32_t state = v * 747796405u + 2891336453u;
  uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

double colorVariationCell(int32_t x, int32_t y) {
  uint32_t cx = static_cast<uint32_t>(x & 255), cy = static_cast<uint32_t>(y & 255);
  uint32_t h = colorVariationPcg(cx + colorVariationPcg(cy));
  return static_cast<double>(h >> 8u) * (1.0 / 16777216.0);
}

double colorVariationNoise(double x, double y) {
  double qx = glsl::mod(x, 256.0), qy = glsl::mod(y, 256.0);
  double ix = std::floor(qx), iy = std::floor(qy);
  double fx = qx - ix, fy = qy - iy;
  double ux = fx * fx * (3.0 - 2.0 * fx), uy = fy * fy * (3.0 - 2.0 * fy);
  auto cx = static_cast<int32_t>(ix), cy = static_cast<int32_t>(iy);
  double a = colorVariationCell(cx, cy), b = colorVariationCell(cx + 1, cy);
  double d = colorVariationCell(cx, cy + 1), e = colorVariationCell(cx + 1, cy + 1);
  return glsl::mix(glsl::mix(a, b, ux), glsl::mix(d, e, ux), uy);
}

Value colorVariationReference(const Value& base, const Value& n, const Value& sun, double height, double noise,
                              double slopeStrength, double noiseStrength, double trough) {
  Value nn = safeNormalize(n), ss = safeNormalize(sun);
  double facing = nn[0] * ss[0] + nn[2] * ss[2];
  Value slope = mixv(vec3(-0.03, -0.01, 0.03), vec3(0.03, 0.05, -0.02), clamp(facing * 0.5 + 0.5, 0.0, 1.0));
  Value hue = mixv(vec3(-0.02, 0.02, 0.04), vec3(0.02, 0.04, -0.02), noise);
  double darken = (1.0 - clamp(height, 0.0, 1.0)) * trough;
  return mul(add(add(base, mul(slope, slopeStrength)), mul(hue, noiseStrength)), 1.0 - darken);
}

double subsurfaceIntensityReference(const Value& n, const Value& v, const Value& l, double distortion, double power,
                                    double height) {
  Value h = safeNormalize(add(safeNormalize(l), mul(safeNormalize(n), distortion)));
  double vdoth = clamp(-dot(safeNormalize(v), h), 0.0, 1.0);
  return glsl::safePow(vdoth, power) * clamp(height * 2.0 + 0.5, 0.0, 1.0);
}

}  // namespace wg::nodes
