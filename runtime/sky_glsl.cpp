// The daylight model as GLSL: the steps of runtime/sky_model.cpp in float, with the
// constants that depend only on the fixed turbidity evaluated here in double and written
// as literals. The Perez distribution runs for Y, x and y at once as a vec3.
#include "runtime/sky_glsl.h"

#include <string>

#include "core/number_format.h"
#include "runtime/sky_model.h"

namespace wg::rt {
namespace {

std::string constFloat(const char* name, double v) { return std::string("const float ") + name + " = " + formatGlslFloat(v) + ";\n"; }

std::string constVec(const char* type, const char* name, std::initializer_list<double> v) {
  std::string s = std::string("const ") + type + " " + name + " = " + type + "(";
  const char* sep = "";
  for (double x : v) {
    s += sep + formatGlslFloat(x);
    sep = ", ";
  }
  return s + ");\n";
}

std::string constArray(const char* name, const double* v, int n) {
  std::string s = std::string("const float ") + name + "[" + std::to_string(n) + "] = float[" + std::to_string(n) + "](";
  for (int i = 0; i < n; ++i) s += (i ? ", " : "") + formatGlslFloat(v[i]);
  return s + ");\n";
}

std::string constants() {
  using namespace sky;
  PerezCoefficients y = perezLuminance(kTurbidity), cx = perezX(kTurbidity), cy = perezY(kTurbidity);
  ZenithLuminanceTerms z = zenithLuminanceTerms(kTurbidity);
  ZenithChromaticityPolynomials p = zenithChromaticityPolynomials(kTurbidity);
  glm::dvec3 tau = sunOpticalDepth();
  std::string s;
  s += constFloat("WG_PI", kPi);
  // Perez coefficients A..E, one vec3 each: (Y, x, y).
  s += constVec("vec3", "WG_PEREZ_A", {y.a, cx.a, cy.a});
  s += constVec("vec3", "WG_PEREZ_B", {y.b, cx.b, cy.b});
  s += constVec("vec3", "WG_PEREZ_C", {y.c, cx.c, cy.c});
  s += constVec("vec3", "WG_PEREZ_D", {y.d, cx.d, cy.d});
  s += constVec("vec3", "WG_PEREZ_E", {y.e, cx.e, cy.e});
  s += constVec("vec3", "WG_ZENITH_LUMINANCE", {z.tanFactor, z.constant, z.chiScale});
  s += constVec("vec4", "WG_ZENITH_X", {p.x[0], p.x[1], p.x[2], p.x[3]});
  s += constVec("vec4", "WG_ZENITH_Y", {p.y[0], p.y[1], p.y[2], p.y[3]});
  s += constFloat("WG_KCD_TO_UNITS", 1000.0 / kRadianceUnitCdPerM2);
  s += constFloat("WG_MIN_COS_ZENITH", kMinCosZenith);
  s += constFloat("WG_TWILIGHT_SCALE", kTwilightScaleDegrees);
  s += constVec("vec3", "WG_NIGHT", {kNightRadiance[0], kNightRadiance[1], kNightRadiance[2]});
  s += constFloat("WG_SUN_RADIUS", kSunAngularRadius);
  s += constFloat("WG_SUN_CHORD", sunDiscChord());
  s += constFloat("WG_SUN_FOOTPRINTS", kSunFootprintWidths);
  s += constFloat("WG_SUN_EDGE", kSunEdgeHalfWidth);
  s += constFloat("WG_SUN_MAX_EDGE", kSunMaxEdgeChord);
  s += constFloat("WG_SUN_SOLID_ANGLE", sunSolidAngle());
  s += constFloat("WG_SUN_TOP_RADIANCE", solarRadianceTopOfAtmosphere());
  s += constFloat("WG_SUN_DISC_CAP", kSunDiscCap);
  s += constVec("vec3", "WG_SUN_OPTICAL_DEPTH", {tau.r, tau.g, tau.b});
  s += constFloat("WG_GROUND_ALBEDO", kGroundAlbedo);
  s += constArray("WG_RING_COS", kIrradianceRingCos, kIrradianceRings);
  s += constArray("WG_RING_WEIGHT", kIrradianceRingWeight, kIrradianceRings);
  return s;
}

// Names and order follow sky_model.cpp; the comments there say why each guard is there.
constexpr const char* kFunctions = R"glsl(
// The angle between unit vectors as atan(|a x b|, a.b): exact near 0, unlike acos(dot),
// and through atan, which drivers approximate more closely than asin and acos.
float wg_angle_between(vec3 a, vec3 b) { return atan(length(cross(a, b)), dot(a, b)); }
// The zenith angle of a unit vector, the same way.
float wg_zenith_angle(vec3 s) { return atan(length(s.xz), s.y); }

// Perez F(theta, gamma) for (Y, x, y): every factor is positive (sky_model.cpp, perez()).
vec3 wg_perez(float cosTheta, float gamma) {
  float cg = cos(gamma);
  return (1.0 + WG_PEREZ_A * exp(WG_PEREZ_B / cosTheta)) * (1.0 + WG_PEREZ_C * exp(WG_PEREZ_D * gamma) + WG_PEREZ_E * cg * cg);
}

// What depends only on the sun: its zenith values over F(0, thetaS) (thetaS at most the
// horizon's) and the twilight fade.
struct WgSky {
  vec3 sun;
  vec3 scale;  // (Y in scene units, x, y) at the zenith / F(0, thetaS)
  float fade;
};

WgSky wg_sky_state(vec3 s) {
  WgSky k;
  k.sun = s;
  float sunZenith = wg_zenith_angle(s);
  float thetaS = min(sunZenith, 0.5 * WG_PI);
  float yz = max(WG_ZENITH_LUMINANCE.x * tan(WG_ZENITH_LUMINANCE.z * (WG_PI - 2.0 * thetaS)) + WG_ZENITH_LUMINANCE.y, 0.0);
  vec4 powers = vec4(thetaS * thetaS * thetaS, thetaS * thetaS, thetaS, 1.0);
  vec3 zenith = vec3(yz * WG_KCD_TO_UNITS, dot(WG_ZENITH_X, powers), dot(WG_ZENITH_Y, powers));
  k.scale = zenith / wg_perez(1.0, thetaS);
  k.fade = exp(min(90.0 - degrees(sunZenith), 0.0) / WG_TWILIGHT_SCALE);
  return k;
}

// xyY to linear Rec.709 (D65), negative channels clamped to 0.
vec3 wg_xyY_to_rgb(float x, float y, float luminance) {
  y = max(y, 1e-4);
  vec3 xyz = vec3(x / y * luminance, luminance, (1.0 - x - y) / y * luminance);
  vec3 rgb = vec3(dot(vec3(3.2404542, -1.5371385, -0.4985314), xyz), dot(vec3(-0.9692660, 1.8760108, 0.0415560), xyz),
                  dot(vec3(0.0556434, -0.2040259, 1.0572252), xyz));
  return max(rgb, vec3(0.0));
}

// The upper hemisphere without the disc (d.y >= 0).
vec3 wg_upper_sky(WgSky k, vec3 d) {
  vec3 yxy = k.scale * wg_perez(max(d.y, WG_MIN_COS_ZENITH), wg_angle_between(d, k.sun));
  return wg_xyY_to_rgb(yxy.y, yxy.z, yxy.x) * k.fade + WG_NIGHT;
}

// Kasten & Young 1989, the zenith angle clamped to [0, 90 deg].
float wg_air_mass(float sunZenith) {
  float z = clamp(sunZenith, 0.0, 0.5 * WG_PI);
  return 1.0 / (cos(z) + 0.50572 * pow(96.07995 - degrees(z), -1.6364));
}

vec3 wg_sun_radiance(vec3 s) {
  return WG_SUN_TOP_RADIANCE * exp(-wg_air_mass(wg_zenith_angle(s)) * WG_SUN_OPTICAL_DEPTH);
}

// The disc as drawn: the hue kept, the largest channel at most WG_SUN_DISC_CAP.
vec3 wg_sun_disc_radiance(vec3 s) {
  vec3 l = wg_sun_radiance(s);
  return l * min(1.0, WG_SUN_DISC_CAP / max(max(max(l.r, l.g), l.b), 1e-30));
}

// Uncapped radiance times the solid angle times the disc's fraction above the horizon.
vec3 wg_sun_irradiance(vec3 s) {
  float h = clamp((0.5 * WG_PI - wg_zenith_angle(s)) / WG_SUN_RADIUS, -1.0, 1.0);
  float visible = 1.0 - (acos(h) - h * sqrt(max(1.0 - h * h, 0.0))) / WG_PI;
  return wg_sun_radiance(s) * (WG_SUN_SOLID_ANGLE * visible);
}

vec3 wg_ground(WgSky k) {
  vec3 horizontal = wg_sun_irradiance(k.sun) * max(k.sun.y, 0.0) + WG_PI * wg_upper_sky(k, vec3(0.0, 1.0, 0.0));
  return WG_GROUND_ALBEDO / WG_PI * horizontal;
}

// The disc's weight at direction d for a pixel of the given footprint (the chord to the
// neighbouring pixels' directions): band-limited to it, its energy kept (sky_model.h,
// sunDiscWeight). q is the squared chord |d - s|^2, accurate near the sun's centre.
float wg_sun_disc_weight(vec3 d, vec3 s, float footprint) {
  float e = clamp(WG_SUN_FOOTPRINTS * footprint, WG_SUN_EDGE, WG_SUN_MAX_EDGE);
  float inner = max(WG_SUN_CHORD - e, 0.0), outer = WG_SUN_CHORD + e;
  inner *= inner;
  outer *= outer;
  vec3 v = d - s;
  float t = clamp((dot(v, v) - inner) / (outer - inner), 0.0, 1.0);
  float w = 1.0 - t;
  return w * w * w * (WG_SUN_CHORD * WG_SUN_CHORD / (inner + 0.25 * (outer - inner)));
}

// The sky in direction d, given what depends only on the sun (k, wg_ground(k) and
// wg_sun_disc_radiance(k.sun)): the sky pass computes those once per draw. footprint: as
// wg_sun_disc_weight's (the caller takes it from derivatives, in uniform control flow).
vec3 wg_sky_radiance(WgSky k, vec3 ground, vec3 disc, vec3 d, float footprint) {
  if (d.y < 0.0) return ground;
  return wg_upper_sky(k, d) + disc * wg_sun_disc_weight(d, k.sun, footprint);
}

// Sky and ground irradiance on a plane of normal n: the radiance against the order-2
// clamped-cosine kernel over Gauss-Legendre rings, plus the ground's exact integral.
vec3 wg_sky_irradiance(vec3 n, vec3 s) {
  WgSky k = wg_sky_state(s);
  float phiS = length(s.xz) > 1e-6 ? atan(s.z, s.x) : 0.0;
  vec3 e = vec3(0.0);
  for (int i = 0; i < WG_RINGS; ++i) {
    float mu = WG_RING_COS[i], sinTheta = sqrt(1.0 - mu * mu);
    float dOmega = WG_RING_WEIGHT[i] * 2.0 * WG_PI / float(WG_AZIMUTHS);
    for (int j = 0; j < WG_AZIMUTHS; ++j) {
      float phi = phiS + 2.0 * WG_PI * float(j) / float(WG_AZIMUTHS);
      vec3 w = vec3(sinTheta * cos(phi), mu, sinTheta * sin(phi));
      float t = dot(n, w);
      e += wg_upper_sky(k, w) * (dOmega * (0.25 + 0.5 * t + 5.0 / 32.0 * (3.0 * t * t - 1.0)));
    }
  }
  e += wg_ground(k) * (0.5 * WG_PI * (1.0 - n.y));
  return max(e, vec3(0.0));
}
)glsl";

}  // namespace

std::string skyGlsl() {
  return "const int WG_RINGS = " + std::to_string(sky::kIrradianceRings) +
         ";\nconst int WG_AZIMUTHS = " + std::to_string(sky::kIrradianceAzimuths) + ";\n" + constants() + kFunctions;
}

}  // namespace wg::rt
