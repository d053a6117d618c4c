#pragma once
// The built-in scene's daylight, in double precision: the reference of the sky and sun
// that runtime/sky_glsl.cpp writes as GLSL for every pass that draws or is lit by the sky.
// The two follow the same steps in the same order (angles come from asin and acos here,
// from atan in the GLSL, which drivers compute more closely). tests/runtime/
// sky_model_test.cpp holds the physics against hand-computed figures and the GPU's sky
// against this file.
//
// Sky: the analytic clear-sky model of Preetham, Shirley and Smits (1999, "A Practical
// Analytic Model for Daylight"): the Perez distribution of luminance Y and chromaticity
// x, y, scaled by the zenith values, at a fixed turbidity kTurbidity.
// Sun: a disc of the sun's angular radius whose radiance is the solar luminance outside
// the atmosphere times the transmittance of Rayleigh and aerosol scattering along the air
// mass of Kasten and Young (1989), at one wavelength per colour channel.
//
// Units: every radiance here is linear Rec.709/sRGB RGB in scene units of
// kRadianceUnitCdPerM2 cd/m^2 (1 unit = 12 kcd/m^2, so the Rec.709 luminance of an RGB
// radiance times 12000 is cd/m^2); irradiances are those units times steradians (1 =
// 12 klux). A Lambertian surface of albedo a under irradiance E has radiance a E / pi.
#include <glm/glm.hpp>

namespace wg::rt::sky {

inline constexpr double kPi = 3.14159265358979323846;

// Turbidity: 2.5 is a clear, dry day (Preetham et al. 1999 cover 2 to ~10; 2 is the
// clearest air they fit).
inline constexpr double kTurbidity = 2.5;

// One scene radiance unit in cd/m^2. Chosen so exposure 0 shows daylight near 1: away
// from the sun the sky reads 0.34 to 0.78 for suns 30 to 60 deg high (the Preetham zenith
// at T = 2.5: 4.3 kcd/m^2 = 0.36 at 30 deg, 8.2 kcd/m^2 = 0.68 at 60 deg), and a white
// Lambertian surface in full sun 1.65 at 30 deg, 2.9 at 60 deg, 3.5 at 90 deg (with 8
// kcd/m^2 it would be 4.4 at 60 deg).
inline constexpr double kRadianceUnitCdPerM2 = 12000.0;

// The sun's mean angular radius (0.2666 deg) and its solid angle 2 pi (1 - cos r), about
// 6.8e-5 sr.
inline constexpr double kSunAngularRadius = 0.2666 * kPi / 180.0;
double sunSolidAngle();

// The disc as drawn is band-limited to the footprint of the target's pixel (the sky
// pass measures it per pixel as the angle to the neighbouring pixels' directions, from
// the derivatives of its view direction), so that a disc smaller than a pixel is not a
// sub-pixel spike that lands in one texel or none depending on where texel centres fall.
// In the squared chord q = |d - s|^2 (= 2 (1 - cos gamma), gamma the angle to the sun's
// centre) the weight is 1 inside q_in = max(c - e, 0)^2, falls as (1 - t)^3 with
// t = (q - q_in) / (q_out - q_in) out to q_out = (c + e)^2, and is 0 beyond; c is the
// disc's chord 2 sin(r / 2) and e the edge's half width, kSunFootprintWidths footprints
// (never less than kSunEdgeHalfWidth, never more than kSunMaxEdgeChord). Since the solid
// angle is dOmega = pi dq, the weight's integral over the sphere is exactly
// pi (q_in + (q_out - q_in) / 4), and the weight is scaled by the disc's own pi c^2 over it:
// the disc's energy (radiance times solid angle) is the same at every footprint. Where the
// pixel is much smaller than the disc it is the sharp disc with an edge a few pixels wide;
// where it is larger, a smooth bump about 2.5 pixels in radius whose sum over any pixel
// grid is its integral to ~0.2 % wherever the disc's centre falls (tests/runtime/
// sun_disc_test.cpp).
inline constexpr double kSunFootprintWidths = 2.5;
inline constexpr double kSunEdgeHalfWidth = 0.02 * kPi / 180.0;
inline constexpr double kSunMaxEdgeChord = 0.5;  // ~29 deg: beyond it no pixel shows a sun
double sunDiscChord();
struct SunDiscShape {
  double inner, outer;  // q_in and q_out, squared chords
  double scale;         // pi c^2 over the weight's integral
};
SunDiscShape sunDiscShape(double footprint);
// The weight at squared chord q, scale included: 1.08 inside the sharp disc (footprint 0),
// up to 1.33 while the flat top shrinks, below 1 once the disc is spread wider than itself.
double sunDiscWeight(double chordSquared, double footprint);

// The luminous solar constant: the sun's illuminance at normal incidence outside the
// atmosphere, about 128 klux (quoted values range from ~127 to ~134 klux). Spread over
// the disc it is a luminance of ~1.9e9 cd/m^2; its colour there is taken as the white of
// Rec.709 (a simplification: the sun outside the atmosphere is near 5800 K).
inline constexpr double kSolarIlluminanceLux = 128000.0;
double solarRadianceTopOfAtmosphere();  // scene units, ~1.57e5

// RGBA16F render targets hold at most 65504. The disc's radiance is scaled (hue kept) so
// that its largest channel is at most kSunDiscCap; lighting uses the uncapped sun. The
// band-limited weight raises the sharp disc's peak by at most ~1.33 (its edge carries less
// than the sharp edge's energy), 40000, still below 65504.
inline constexpr double kSunDiscCap = 30000.0;

// The ground below the horizon: a Lambertian plane of this albedo (grass and soil ~0.2)
// lit by the sun and a sky of the zenith's radiance.
inline constexpr double kGroundAlbedo = 0.2;

// Below the horizon the daylight model does not apply: its sky is evaluated for a sun on
// the horizon and dimmed by exp(elevation / kTwilightScaleDegrees), about 1/55 at -6 deg
// (civil twilight's end) and 3e-4 at -12 deg; kNightRadiance (scene units, a dark blue
// of luminance ~1e-4 units = 1.2 cd/m^2, deep dusk) is added everywhere so no
// direction is ever black or negative.
inline constexpr double kTwilightScaleDegrees = 1.5;
inline constexpr double kNightRadiance[3] = {0.00006, 0.0001, 0.00016};

// The view direction's cos(zenith angle) used by the Perez distribution is at least this:
// its term exp(B / cos theta) (B < 0) vanishes towards the horizon, and the floor keeps
// the division finite.
inline constexpr double kMinCosZenith = 0.01;

// --- the parts, exposed for tests ---------------------------------------------------
// Preetham et al. 1999, eq. in appendix A.2: the zenith luminance in kcd/m^2 for
// turbidity t and sun zenith angle thetaS (radians); may be negative far below the
// horizon (the formula's own range ends at the horizon).
double preethamZenithLuminance(double turbidity, double thetaS);
// Its terms for one turbidity: Yz = tanFactor tan(chiScale (pi - 2 thetaS)) + constant.
struct ZenithLuminanceTerms {
  double tanFactor, constant, chiScale;
};
ZenithLuminanceTerms zenithLuminanceTerms(double turbidity);
// Zenith chromaticity (x, y), appendix A.2's polynomials in T and thetaS.
glm::dvec2 preethamZenithChromaticity(double turbidity, double thetaS);
// The same polynomials with T folded in: x = dot(x, (thetaS^3, thetaS^2, thetaS, 1)).
struct ZenithChromaticityPolynomials {
  glm::dvec4 x, y;
};
ZenithChromaticityPolynomials zenithChromaticityPolynomials(double turbidity);
// The Perez distribution F(theta, gamma) for the coefficients A..E.
struct PerezCoefficients {
  double a, b, c, d, e;
};
double perez(const PerezCoefficients& k, double cosTheta, double gamma);
// The turbidity-linear coefficients for Y, x and y (appendix A.2).
PerezCoefficients perezLuminance(double turbidity);
PerezCoefficients perezX(double turbidity);
PerezCoefficients perezY(double turbidity);
// xyY (Y in scene units) to linear Rec.709 RGB, negative channels clamped to 0.
glm::dvec3 xyYToLinearRgb(double x, double y, double luminance);
// Relative optical air mass for a sun zenith angle (radians), Kasten & Young 1989; the
// angle is clamped to [0, 90 deg] (38.1 at the horizon).
double airMass(double sunZenith);
// Transmittance of the direct beam for the channels' wavelengths (0.65, 0.55, 0.45 um):
// exp(-m (tau_Rayleigh + tau_aerosol)).
glm::dvec3 sunTransmittance(double sunZenith);
// The optical depths at unit air mass tau_R + tau_A per channel (~0.17, 0.25, 0.42).
glm::dvec3 sunOpticalDepth();

// --- the model ----------------------------------------------------------------------
// Directions need not be unit; a zero vector is treated as straight up.
// The sky without the sun disc: Preetham above the horizon, the ground below it.
glm::dvec3 diffuseSkyRadiance(glm::dvec3 direction, glm::dvec3 sunDirection);
// What the sky pass draws into a pixel of the given footprint (radians: the chord to
// the neighbouring pixels' directions): the diffuse sky plus the (capped) sun disc
// band-limited to that footprint.
glm::dvec3 skyRadiance(glm::dvec3 direction, glm::dvec3 sunDirection, double footprint);
// The sun's radiance at the ground, uncapped (scene units).
glm::dvec3 sunRadiance(glm::dvec3 sunDirection);
// The disc's radiance as drawn: sunRadiance scaled to at most kSunDiscCap.
glm::dvec3 sunDiscRadiance(glm::dvec3 sunDirection);
// Irradiance from the sun on a plane facing it: uncapped radiance times the solid angle
// times the fraction of the disc above the horizon.
glm::dvec3 sunIrradiance(glm::dvec3 sunDirection);
// The ground's radiance (every direction below the horizon).
glm::dvec3 groundRadiance(glm::dvec3 sunDirection);
// Irradiance on a plane of unit normal `normal` from the sky and ground (no sun disc), as
// the opaque scene computes it: the radiance projected onto spherical harmonics up to
// order 2 and convolved with the clamped cosine (Ramamoorthi & Hanrahan 2001), which is
// the radiance integrated against the kernel K(t) = 1/4 + t/2 + 5/32 (3 t^2 - 1) of
// t = n.w. The sky's integral is a fixed quadrature (Gauss-Legendre rings in cos(zenith)
// of the upper hemisphere, azimuths from the sun's), the ground's is exact. Against a fine
// integral of radiance times max(n.w, 0) it is within 5 % for the normals and sun
// elevations sky_model_test checks (order 1 alone was off by up to 45 %).
inline constexpr int kIrradianceRings = 6, kIrradianceAzimuths = 12;
// The 6-point Gauss-Legendre rule moved to [0, 1]: nodes (cos zenith) and weights.
inline constexpr double kIrradianceRingCos[kIrradianceRings] = {0.0337652428984240, 0.1693953067668677,
                                                                0.3806904069584015, 0.6193095930415985,
                                                                0.8306046932331323, 0.9662347571015760};
inline constexpr double kIrradianceRingWeight[kIrradianceRings] = {0.0856622461895852, 0.1803807865240693,
                                                                   0.2339569672863455, 0.2339569672863455,
                                                                   0.1803807865240693, 0.0856622461895852};
double irradianceKernel(double t);
glm::dvec3 skyIrradiance(glm::dvec3 normal, glm::dvec3 sunDirection);

}  // namespace wg::rt::sky
