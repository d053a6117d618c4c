#pragma once
// Double-precision references of the optics, depth-and-colour and scattering nodes
// (reflect_dir, refract_dir, lambert, blinn_phong, phong_specular, ggx_specular,
// linearize_depth, water_depth, absorption, haze, color_variation, subsurface). Each
// mirrors its GLSL function in nodes/glsl/ (same clamps, same guards), except where the
// GLSL takes another road to the same value for float32's sake (blinn_phong's and
// ggx_specular's half vector and their terms near the lobe's peak: the textbook form,
// exact in double, is kept here); the nodes' eval and their tests share them.
#include <cstdint>

#include "core/value.h"

namespace wg::nodes {

// reflect(-V, N) with safe normalisation of inputs and result (reflect_dir.glsl).
Value reflectDirReference(const Value& n, const Value& v);

struct Refraction {
  Value direction;  // unit refracted direction, or the mirror reflection under TIR
  bool tir = false;
};
// eta = n_viewer / n_other (refract_dir.glsl).
Refraction refractDirReference(const Value& n, const Value& v, double eta);

double lambertReference(const Value& n, const Value& l);
double blinnPhongSpecularReference(const Value& n, const Value& v, const Value& l, double shininess);
double phongSpecularLobeReference(const Value& n, const Value& v, const Value& l);

struct GgxTerms {
  double brdf = 0;   // D F G / (4 NdotL NdotV)
  double d = 0;      // GGX distribution
  double f = 0;      // Schlick Fresnel at V.H
  double ndotl = 0;  // clamped N.L
};
double ggxDistributionReference(double ndoth, double a2);
double ggxVisibilityReference(double ndotl, double ndotv, double roughness);
GgxTerms ggxSpecularReference(const Value& n, const Value& v, const Value& l, double roughness, double f0);
// Beckmann exp(-tan^2 / a2) / (pi a2 cos^4), 0 where the exponent passes 80 (as the GLSL).
double ggxBeckmannReference(double ndoth, double a2);
// The filtered lobe for facet slopes of total variance `variance` around N
// (wg_ggx_specular_filtered): ggxSpecularReference where the variance is not above 0;
// ndotl is the reflecting facets' N*.L.
GgxTerms ggxSpecularFilteredReference(const Value& n, const Value& v, const Value& l, double roughness,
                                      double variance, double f0);

// n / ((1 - d) + d n / f), guarded as linearize_depth.glsl; never above kMaxLinearDepth.
inline constexpr double kMaxLinearDepth = 1e30;
double linearizeDepthReference(double depth, double nearPlane, double farPlane);
// Its per-draw part (near_far_ratio): n = max(near, 1e-6) and r = n / max(far, n)...
struct NearFarRatio {
  double nearPlane, ratio;
};
NearFarRatio nearFarRatioReference(double nearPlane, double farPlane);
// ...and the per-pixel rest, given n and r.
double linearizeDepthRatioReference(double depth, double n, double r);
// `view` is a column-major mat4 Value.
double waterDepthRayFactorReference(const Value& view, const Value& v);
// The same from the camera's unit axis (camera_forward: zero for a degenerate view matrix).
double waterDepthRayFactorAxisReference(const Value& axis, const Value& v);
double waterDepthThicknessReference(double sceneLinear, double surfaceLinear, double factor, double vertical);

Value beerLambertReference(const Value& sigma, double distance);
Value relativeAbsorptionReference(double distance, double maxDistance, double kRed, double kGreen);
double hazeFactorReference(double distance, double hazeDistance);

uint32_t colorVariationPcg(uint32_t v);
double colorVariationCell(int32_t x, int32_t y);
double colorVariationNoise(double x, double y);
Value colorVariationReference(const Value& base, const Value& n, const Value& sun, double height, double noise,
                              double slopeStrength, double noiseStrength, double trough);

double subsurfaceIntensityReference(const Value& n, const Value& v, const Value& l, double distortion, double power,
                                    double height);

}  // namespace wg::nodes
