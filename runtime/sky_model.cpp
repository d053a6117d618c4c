// The daylight model in double precision (see sky_model.h). Every step here has its twin,
// in the same order, in the GLSL of runtime/sky_glsl.cpp.
#include "runtime/sky_model.h"

#include <algorithm>
#include <cmath>

namespace wg::rt::sky {
namespace {

constexpr double kDegrees = 180.0 / kPi;

glm::dvec3 unitOrUp(glm::dvec3 v) {
  double len = glm::length(v);
  return len > 1e-30 ? v / len : glm::dvec3(0.0, 1.0, 0.0);
}

// The angle between two unit vectors from their chord, 2 asin(|a - b| / 2): exact to a
// few ulps near 0, where acos(dot) would lose half the digits (the sun's radius is
// 4.7e-3 rad: 1 - cos r = 1.1e-5, only ~100 float32 steps).
double angleBetween(glm::dvec3 a, glm::dvec3 b) { return 2.0 * std::asin(std::min(1.0, glm::length(a - b) * 0.5)); }

// The sun's zenith angle in [0, pi].
double sunZenith(glm::dvec3 s) { return std::acos(std::clamp(s.y, -1.0, 1.0)); }

// The Preetham sky above the horizon (direction.y >= 0 assumed), before the twilight fade.
glm::dvec3 preethamSky(glm::dvec3 d, glm::dvec3 s) {
  // The model's range ends with the sun on the horizon: below it, the sky of a sun on the
  // horizon (the distribution around the true sun direction is still finite: every
  // factor of F stays positive, see perez()).
  double thetaS = std::min(sunZenith(s), kPi / 2.0);
  double cosTheta = std::max(d.y, kMinCosZenith);
  double gamma = angleBetween(d, s);
  PerezCoefficients kY = perezLuminance(kTurbidity), kx = perezX(kTurbidity), ky = perezY(kTurbidity);
  glm::dvec2 xyZenith = preethamZenithChromaticity(kTurbidity, thetaS);
  double yZenith = std::max(preethamZenithLuminance(kTurbidity, thetaS), 0.0);  // kcd/m^2
  double luminance = yZenith * perez(kY, cosTheta, gamma) / perez(kY, 1.0, thetaS);
  double x = xyZenith.x * perez(kx, cosTheta, gamma) / perez(kx, 1.0, thetaS);
  double y = xyZenith.y * perez(ky, cosTheta, gamma) / perez(ky, 1.0, thetaS);
  return xyYToLinearRgb(x, y, luminance * 1000.0 / kRadianceUnitCdPerM2);
}

// The upper hemisphere's sky (no disc): Preetham, faded below the horizon, plus night.
glm::dvec3 upperSky(glm::dvec3 d, glm::dvec3 s) {
  double elevationDegrees = 90.0 - sunZenith(s) * kDegrees;
  double fade = std::exp(std::min(elevationDegrees, 0.0) / kTwilightScaleDegrees);
  return preethamSky(d, s) * fade + glm::dvec3(kNightRadiance[0], kNightRadiance[1], kNightRadiance[2]);
}

}  // namespace

double irradianceKernel(double t) { return 0.25 + 0.5 * t + 5.0 / 32.0 * (3.0 * t * t - 1.0); }

double sunSolidAngle() { return 2.0 * kPi * (1.0 - std::cos(kSunAngularRadius)); }

double solarRadianceTopOfAtmosphere() { return kSolarIlluminanceLux / sunSolidAngle() / kRadianceUnitCdPerM2; }

ZenithLuminanceTerms zenithLuminanceTerms(double t) {
  return {4.0453 * t - 4.9710, -0.2155 * t + 2.4192, 4.0 / 9.0 - t / 120.0};
}

double preethamZenithLuminance(double t, double thetaS) {
  ZenithLuminanceTerms k = zenithLuminanceTerms(t);
  return k.tanFactor * std::tan(k.chiScale * (kPi - 2.0 * thetaS)) + k.constant;
}

ZenithChromaticityPolynomials zenithChromaticityPolynomials(double t) {
  // [T^2 T 1] M [thetaS^3 thetaS^2 thetaS 1]^T: each matrix's rows for T^2, T and 1.
  glm::dvec3 powers(t * t, t, 1.0);
  glm::dmat4x3 mx(glm::dvec3(0.00166, -0.02903, 0.11693), glm::dvec3(-0.00375, 0.06377, -0.21196),
                  glm::dvec3(0.00209, -0.03202, 0.06052), glm::dvec3(0.0, 0.00394, 0.25886));
  glm::dmat4x3 my(glm::dvec3(0.00275, -0.04214, 0.15346), glm::dvec3(-0.00610, 0.08970, -0.26756),
                  glm::dvec3(0.00317, -0.04153, 0.06670), glm::dvec3(0.0, 0.00516, 0.26688));
  return {powers * mx, powers * my};
}

glm::dvec2 preethamZenithChromaticity(double t, double thetaS) {
  ZenithChromaticityPolynomials p = zenithChromaticityPolynomials(t);
  glm::dvec4 s(thetaS * thetaS * thetaS, thetaS * thetaS, thetaS, 1.0);
  return {glm::dot(p.x, s), glm::dot(p.y, s)};
}

double perez(const PerezCoefficients& k, double cosTheta, double gamma) {
  // (1 + A e^(B / cos theta)) (1 + C e^(D gamma) + E cos^2 gamma). At T = 2.5 every A and
  // B is negative and C, E positive, so the first factor lies in [1 + A e^B, 1] (>= 0.35)
  // and the second is >= 1: F > 0 for every direction.
  double cg = std::cos(gamma);
  return (1.0 + k.a * std::exp(k.b / cosTheta)) * (1.0 + k.c * std::exp(k.d * gamma) + k.e * cg * cg);
}

PerezCoefficients perezLuminance(double t) {
  return {0.1787 * t - 1.4630, -0.3554 * t + 0.4275, -0.0227 * t + 5.3251, 0.1206 * t - 2.5771, -0.0670 * t + 0.3703};
}
PerezCoefficients perezX(double t) {
  return {-0.0193 * t - 0.2592, -0.0665 * t + 0.0008, -0.0004 * t + 0.2125, -0.0641 * t - 0.8989, -0.0033 * t + 0.0452};
}
PerezCoefficients perezY(double t) {
  return {-0.0167 * t - 0.2608, -0.0950 * t + 0.0092, -0.0079 * t + 0.2102, -0.0441 * t - 1.6537, -0.0109 * t + 0.0529};
}

glm::dvec3 xyYToLinearRgb(double x, double y, double luminance) {
  y = std::max(y, 1e-4);
  double bigX = x / y * luminance, bigZ = (1.0 - x - y) / y * luminance;
  // XYZ to linear Rec.709 (D65 white), IEC 61966-2-1.
  glm::dvec3 rgb(3.2404542 * bigX - 1.5371385 * luminance - 0.4985314 * bigZ,
                 -0.9692660 * bigX + 1.8760108 * luminance + 0.0415560 * bigZ,
                 0.0556434 * bigX - 0.2040259 * luminance + 1.0572252 * bigZ);
  return glm::max(rgb, glm::dvec3(0.0));
}

double airMass(double sunZenith) {
  double z = std::clamp(sunZenith, 0.0, kPi / 2.0);
  return 1.0 / (std::cos(z) + 0.50572 * std::pow(96.07995 - z * kDegrees, -1.6364));
}

glm::dvec3 sunTransmittance(double sunZenith) {
  return glm::exp(-airMass(sunZenith) * sunOpticalDepth());
}

glm::dvec3 sunOpticalDepth() {
  // At 0.65, 0.55, 0.45 um: Rayleigh 0.008735 lambda^-4.08, aerosol beta lambda^-1.3 with
  // Preetham's beta = 0.04608 T - 0.04586 (appendix A.3).
  double beta = 0.04608 * kTurbidity - 0.04586;
  glm::dvec3 lambda(0.65, 0.55, 0.45), tau;
  for (int i = 0; i < 3; ++i) tau[i] = 0.008735 * std::pow(lambda[i], -4.08) + beta * std::pow(lambda[i], -1.3);
  return tau;
}

glm::dvec3 sunRadiance(glm::dvec3 sunDirection) {
  return solarRadianceTopOfAtmosphere() * sunTransmittance(sunZenith(unitOrUp(sunDirection)));
}

glm::dvec3 sunDiscRadiance(glm::dvec3 sunDirection) {
  glm::dvec3 l = sunRadiance(sunDirection);
  double peak = std::max(std::max(l.r, l.g), l.b);
  return l * std::min(1.0, kSunDiscCap / std::max(peak, 1e-30));
}

double sunDiscChord() { return 2.0 * std::sin(kSunAngularRadius / 2.0); }

SunDiscShape sunDiscShape(double footprint) {
  double c = sunDiscChord();
  double e = std::clamp(kSunFootprintWidths * footprint, kSunEdgeHalfWidth, kSunMaxEdgeChord);
  double inner = std::max(c - e, 0.0), outer = c + e;
  inner *= inner;
  outer *= outer;
  return {inner, outer, c * c / (inner + 0.25 * (outer - inner))};
}

double sunDiscWeight(double chordSquared, double footprint) {
  SunDiscShape k = sunDiscShape(footprint);
  double t = std::clamp((chordSquared - k.inner) / (k.outer - k.inner), 0.0, 1.0);
  double w = 1.0 - t;
  return w * w * w * k.scale;
}

glm::dvec3 sunIrradiance(glm::dvec3 sunDirection) {
  // The part of a disc of unit radius above a line h (its centre's height in radii)
  // below its centre: 1 - (acos h - h sqrt(1 - h^2)) / pi, 0 at h = -1, 1/2 at 0, 1 at 1.
  glm::dvec3 s = unitOrUp(sunDirection);
  double elevation = kPi / 2.0 - sunZenith(s);
  double h = std::clamp(elevation / kSunAngularRadius, -1.0, 1.0);
  double visible = 1.0 - (std::acos(h) - h * std::sqrt(std::max(1.0 - h * h, 0.0))) / kPi;
  return sunRadiance(s) * sunSolidAngle() * visible;
}

glm::dvec3 groundRadiance(glm::dvec3 sunDirection) {
  glm::dvec3 s = unitOrUp(sunDirection);
  glm::dvec3 horizontal = sunIrradiance(s) * std::max(s.y, 0.0) + kPi * upperSky(glm::dvec3(0.0, 1.0, 0.0), s);
  return kGroundAlbedo / kPi * horizontal;
}

glm::dvec3 diffuseSkyRadiance(glm::dvec3 direction, glm::dvec3 sunDirection) {
  glm::dvec3 d = unitOrUp(direction), s = unitOrUp(sunDirection);
  return d.y < 0.0 ? groundRadiance(s) : upperSky(d, s);
}

glm::dvec3 skyRadiance(glm::dvec3 direction, glm::dvec3 sunDirection, double footprint) {
  glm::dvec3 d = unitOrUp(direction), s = unitOrUp(sunDirection);
  if (d.y < 0.0) return groundRadiance(s);
  glm::dvec3 v = d - s;
  return upperSky(d, s) + sunDiscRadiance(s) * sunDiscWeight(glm::dot(v, v), footprint);
}

glm::dvec3 skyIrradiance(glm::dvec3 normal, glm::dvec3 sunDirection) {
  glm::dvec3 n = unitOrUp(normal), s = unitOrUp(sunDirection);
  double horizontalLength = std::sqrt(s.x * s.x + s.z * s.z);
  double phiS = horizontalLength > 1e-6 ? std::atan2(s.z, s.x) : 0.0;
  glm::dvec3 e(0.0);
  for (int i = 0; i < kIrradianceRings; ++i) {
    double mu = kIrradianceRingCos[i], sinTheta = std::sqrt(1.0 - mu * mu);
    double dOmega = kIrradianceRingWeight[i] * 2.0 * kPi / kIrradianceAzimuths;
    for (int j = 0; j < kIrradianceAzimuths; ++j) {
      double phi = phiS + 2.0 * kPi * j / kIrradianceAzimuths;
      glm::dvec3 w(sinTheta * std::cos(phi), mu, sinTheta * std::sin(phi));
      e += upperSky(w, s) * (dOmega * irradianceKernel(glm::dot(n, w)));
    }
  }
  // The ground, one radiance over the lower hemisphere: the kernel's integral there is
  // (pi / 2) (1 - n.y) (its order-2 part integrates to 0 over a hemisphere).
  e += groundRadiance(s) * (kPi / 2.0 * (1.0 - n.y));
  return glm::max(e, glm::dvec3(0.0));
}

}  // namespace wg::rt::sky
