// The built-in scene's daylight (runtime/sky_model.h, runtime/sky_glsl.cpp): the double
// reference against Preetham's formulas worked by hand and against the ratios daylight
// must show; the sky the GPU draws against the reference, pixel by pixel; the hard
// directions and sun elevations, each shown to reach the guard it is there for; and the
// sun disc's colour, which fails if the GLSL drew no disc or no transmittance.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "runtime/egl_context.h"
#include "runtime/renderer.h"
#include "runtime/sky_glsl.h"
#include "runtime/sky_model.h"
#include "runtime_test_support.h"

namespace wg::rt {
namespace {

using namespace sky;

constexpr double kDeg = kPi / 180.0;

glm::dvec3 direction(double elevationDegrees, double azimuthDegrees) {
  // As scene.h's sunDirection: azimuth from +x towards +z.
  double e = elevationDegrees * kDeg, a = azimuthDegrees * kDeg;
  return {std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a)};
}

double luminance(glm::dvec3 rgb) { return 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b; }

bool finiteNonNegative(glm::dvec3 v) {
  return std::isfinite(v.r) && std::isfinite(v.g) && std::isfinite(v.b) && v.r >= 0 && v.g >= 0 && v.b >= 0;
}

// --- the reference's physics ----------------------------------------------------------

TEST(SkyModel, ZenithLuminanceIsPreethamsFormula) {
  // Yz = (4.0453 T - 4.9710) tan chi - 0.2155 T + 2.4192 kcd/m^2,
  // chi = (4/9 - T/120)(pi - 2 thetaS), worked by hand:
  //   T = 2.5, thetaS = 30 deg: chi = 0.4236111 * 2.0943951 = 0.88721; tan = 1.22758;
  //     Yz = 5.14225 * 1.22758 + 1.88045 = 8.193
  //   T = 2.5, thetaS = 60 deg: chi = 0.44360; tan = 0.47519; Yz = 4.324
  //   T = 4,   thetaS = 45 deg: chi = (0.4444444 - 0.0333333) * 1.5707963 = 0.64577;
  //     tan = 0.75355; Yz = 11.2102 * 0.75355 + 1.5572 = 10.005
  struct Case {
    double t, thetaSDegrees, figure;
  };
  for (Case c : {Case{2.5, 30, 8.193}, Case{2.5, 60, 4.324}, Case{4.0, 45, 10.005}}) {
    SCOPED_TRACE(testing::Message() << "T " << c.t << ", thetaS " << c.thetaSDegrees);
    double thetaS = c.thetaSDegrees * kDeg;
    double chi = (4.0 / 9.0 - c.t / 120.0) * (kPi - 2.0 * thetaS);
    double byHand = (4.0453 * c.t - 4.9710) * std::tan(chi) - 0.2155 * c.t + 2.4192;
    EXPECT_NEAR(preethamZenithLuminance(c.t, thetaS), byHand, 1e-12);
    EXPECT_NEAR(preethamZenithLuminance(c.t, thetaS), c.figure, 2e-3);
  }
  // Zenith chromaticity at T = 2.5, thetaS = 30 deg (0.5236 rad), the paper's matrices by
  // hand: x = 0.05473 s^3 - 0.0759725 s^2 - 0.0064675 s + 0.26871 = 0.2523,
  // y = 0.0652975 s^3 - 0.081435 s^2 - 0.0173125 s + 0.27978 = 0.2578.
  glm::dvec2 xy = preethamZenithChromaticity(2.5, 30 * kDeg);
  EXPECT_NEAR(xy.x, 0.2523, 2e-4);
  EXPECT_NEAR(xy.y, 0.2578, 2e-4);
}

TEST(SkyModel, TheZenithHasPreethamsLuminanceInSceneUnits) {
  // F(theta, gamma) / F(0, thetaS) is 1 at the zenith, so the drawn zenith's luminance is
  // Yz (kcd/m^2) * 1000 / 12000 plus the night floor: the xyY -> RGB chain and the unit.
  for (double elevation : {20.0, 45.0, 70.0}) {
    SCOPED_TRACE(elevation);
    glm::dvec3 sun = direction(elevation, 110);
    double expected = preethamZenithLuminance(kTurbidity, (90 - elevation) * kDeg) * 1000.0 / kRadianceUnitCdPerM2;
    double night = luminance(glm::dvec3(kNightRadiance[0], kNightRadiance[1], kNightRadiance[2]));
    EXPECT_NEAR(luminance(diffuseSkyRadiance({0, 1, 0}, sun)) - night, expected, 1e-3 * expected);
  }
}

TEST(SkyModel, DaylightRatiosHold) {
  glm::dvec3 sun = direction(30, 110);
  // Brighter towards the sun than away from it, at equal elevation.
  for (double e : {5.0, 20.0, 45.0}) {
    SCOPED_TRACE(e);
    EXPECT_GT(luminance(skyRadiance(direction(e, 110 + 40), sun, 0.0)), 1.2 * luminance(skyRadiance(direction(e, 110 + 180), sun, 0.0)));
  }
  // The disc is thousands of times the zenith (here 7.2e4, the disc being capped).
  double zenith = luminance(skyRadiance({0, 1, 0}, sun, 0.0));
  EXPECT_GE(luminance(skyRadiance(sun, sun, 0.0)), 1e3 * zenith);
  // The uncapped sun: 1.57e5 units outside the atmosphere (128 klux over 6.8e-5 sr,
  // / 12000 cd/m^2), 9.7e4 in luminance after the air mass at 30 deg.
  EXPECT_NEAR(solarRadianceTopOfAtmosphere(), 128000.0 / 6.8018e-5 / 12000.0, 10.0);
  EXPECT_NEAR(luminance(sunRadiance(sun)), 96521, 10);
  EXPECT_LE(std::max({sunDiscRadiance(sun).r, sunDiscRadiance(sun).g, sunDiscRadiance(sun).b}), kSunDiscCap);
  // Sunset is redder than noon.
  glm::dvec3 low = sunRadiance(direction(5, 0)), high = sunRadiance(direction(60, 0));
  EXPECT_GT(low.r / low.b, 2.0 * (high.r / high.b));
  // Kasten & Young: 1 at the zenith, 1.994 at 60 deg, 37.92 at the horizon.
  EXPECT_NEAR(airMass(0), 1.0, 1e-3);
  EXPECT_NEAR(airMass(60 * kDeg), 1.994, 1e-3);
  EXPECT_NEAR(airMass(90 * kDeg), 37.92, 0.01);
}

TEST(SkyModel, DaylightReadsNearOneAtExposureZero) {
  // The unit's promise (sky_model.h): a daylight sky away from the sun ~0.3 to 1.5, a white
  // Lambertian surface in full sun ~1 to 3 (1.65 at 30 deg, 2.94 at 60 deg).
  for (double elevation : {30.0, 45.0, 60.0}) {
    SCOPED_TRACE(elevation);
    glm::dvec3 sun = direction(elevation, 110);
    for (double az : {110.0 + 90, 110.0 + 180})
      for (double e : {10.0, 45.0, 90.0}) {
        double l = luminance(skyRadiance(direction(e, az), sun, 0.0));
        EXPECT_GT(l, 0.3);
        EXPECT_LT(l, 1.5);
      }
    glm::dvec3 white = (sunIrradiance(sun) * sun.y + skyIrradiance({0, 1, 0}, sun)) / kPi;
    EXPECT_GT(luminance(white), 1.0);
    EXPECT_LT(luminance(white), 3.0);
  }
}

TEST(SkyModel, SkyIrradianceIsTheIntegralOfTheSky) {
  // Against a 300 x 600 midpoint integral of radiance * max(n.w, 0) over the sphere: the
  // order-2 kernel over 72 samples is within 6 %.
  auto exact = [](glm::dvec3 n, glm::dvec3 sun) {
    const int rows = 300;
    glm::dvec3 e(0.0);
    for (int i = 0; i < rows; ++i) {
      double mu = -1.0 + 2.0 * (i + 0.5) / rows, st = std::sqrt(1.0 - mu * mu);
      for (int j = 0; j < 2 * rows; ++j) {
        double phi = 2.0 * kPi * (j + 0.5) / (2 * rows);
        glm::dvec3 w(st * std::cos(phi), mu, st * std::sin(phi));
        double c = glm::dot(n, w);
        if (c > 0) e += diffuseSkyRadiance(w, sun) * c * (2.0 / rows) * (kPi / rows);
      }
    }
    return e;
  };
  for (double elevation : {60.0, 10.0, 0.0}) {
    glm::dvec3 sun = direction(elevation, 110);
    for (glm::dvec3 n : {glm::dvec3(0, 1, 0), direction(0, 110), direction(0, 290), direction(45, 200), direction(-60, 0)}) {
      SCOPED_TRACE(testing::Message() << "sun " << elevation << ", n " << n.x << " " << n.y << " " << n.z);
      glm::dvec3 a = skyIrradiance(n, sun), b = exact(n, sun);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 0.06 * b[c]);
    }
  }
  // The sun's irradiance is its radiance times its solid angle (sun well above the
  // horizon), half of it with the disc's centre on the horizon, none below.
  glm::dvec3 sun = direction(40, 0);
  EXPECT_NEAR(sunIrradiance(sun).g, sunRadiance(sun).g * sunSolidAngle(), 1e-9);
  EXPECT_NEAR(sunIrradiance(direction(0, 0)).g, 0.5 * sunRadiance(direction(0, 0)).g * sunSolidAngle(), 1e-9);
  EXPECT_EQ(sunIrradiance(direction(-1, 0)).g, 0.0);
}

TEST(SkyModel, HardCasesAreFiniteAndNonNegativeAndReachTheirGuards) {
  glm::dvec3 horizonSun = direction(0, 110), belowSun = direction(-10, 110);
  // The sun exactly on the horizon: the model's zenith angle is pi/2, chi = 0, Yz = the
  // formula's constant; half the disc is drawn.
  EXPECT_NEAR(preethamZenithLuminance(kTurbidity, kPi / 2), -0.2155 * kTurbidity + 2.4192, 1e-12);
  // 10 deg below: the formula alone would give a zenith thetaS = 100 deg (still positive,
  // 1.11 kcd/m^2, and its chromaticity polynomial leaves the gamut further down: x = 1.2
  // at thetaS = 180 deg); the model uses the horizon's sky dimmed by exp(-10 / 1.5).
  EXPECT_GT(preethamZenithChromaticity(kTurbidity, kPi).x, 1.0);
  double ratio = luminance(diffuseSkyRadiance({0, 1, 0}, belowSun)) / luminance(diffuseSkyRadiance({0, 1, 0}, horizonSun));
  EXPECT_NEAR(ratio, std::exp(-10.0 / kTwilightScaleDegrees), 1e-3);
  // Far below, Yz is negative (-19 kcd/m^2 at -90 deg): clamped, the night floor remains.
  EXPECT_LT(preethamZenithLuminance(kTurbidity, kPi), 0.0);
  glm::dvec3 night = skyRadiance({0, 1, 0}, direction(-90, 0), 0.0);
  EXPECT_NEAR(night.b, kNightRadiance[2], 1e-6);
  std::vector<glm::dvec3> suns = {direction(90, 0), direction(30, 110), horizonSun, belowSun, direction(-90, 0),
                                  glm::dvec3(0.0)};
  for (glm::dvec3 sun : suns) {
    std::vector<glm::dvec3> views = {{0, 1, 0},       {0, -1, 0},   direction(0, 20), direction(0, 110),
                                     {1, 1e-12, 0},  sun,          direction(0.001, 110),
                                     glm::dvec3(0.0)};
    for (glm::dvec3 d : views) {
      SCOPED_TRACE(testing::Message() << "sun " << sun.x << " " << sun.y << " " << sun.z << ", view " << d.x << " " << d.y
                                      << " " << d.z);
      for (double footprint : {0.0, 0.0156, 10.0}) EXPECT_TRUE(finiteNonNegative(skyRadiance(d, sun, footprint)));
      EXPECT_TRUE(finiteNonNegative(skyIrradiance(d, sun)));
    }
    EXPECT_TRUE(finiteNonNegative(sunIrradiance(sun)));
  }
  // Straight down is the ground; at the horizon the Perez term uses the floor cos theta.
  glm::dvec3 sun = direction(30, 110);
  EXPECT_EQ(skyRadiance({0, -1, 0}, sun, 0.0), groundRadiance(sun));
  // cos theta = 0 is raised to kMinCosZenith: the horizon's radiance joins the sky just
  // above it (0.57 deg up) within 1 %.
  glm::dvec3 horizon = direction(0, 20), above = direction(std::asin(kMinCosZenith) / kDeg, 20);
  EXPECT_NEAR(luminance(diffuseSkyRadiance(horizon, sun)), luminance(diffuseSkyRadiance(above, sun)),
              0.01 * luminance(diffuseSkyRadiance(above, sun)));
  // At the sun, the disc: its capped radiance on top of the sky.
  EXPECT_GE(skyRadiance(sun, sun, 0.0).r, sunDiscRadiance(sun).r);
}

// --- the GPU against the reference ---------------------------------------------------

// A camera far from the scene's meshes (they lie within ~25 m of the origin and the far
// plane is 200 m), so every pixel is the sky pass, whichever way it looks.
Camera skyCamera(glm::dvec3 view, float fovDegrees) {
  Camera c;
  c.position = {300.0f, 50.0f, 300.0f};
  c.target = c.position + glm::vec3(view);
  c.fovYDegrees = fovDegrees;
  return c;
}

struct SkyFrame {
  Image image;
  glm::dmat4 inverseViewProjection;
};

SkyFrame renderSky(EglContext& ctx, const Camera& camera, double sunElevation, double sunAzimuth, int size = 64) {
  RenderSettings s = test::smallSettings();
  s.width = s.height = size;
  s.customCamera = camera;
  s.floatColor = true;
  s.waterGridQuads = 1;
  s.scene.sunElevationDegrees = static_cast<float>(sunElevation);
  s.scene.sunAzimuthDegrees = static_cast<float>(sunAzimuth);
  Renderer r(Manifest::fromJson(test::handManifest({}, {})), test::handWaterShaders(ctx.isEs(), {}), s, ctx.isEs());
  r.renderFrame();
  glm::mat4 vp = camera.projection(1.0f) * camera.view();
  return {r.readRgba32f(), glm::inverse(glm::dmat4(vp))};
}

// The view direction of pixel (column, row; rows top to bottom) as the sky shader builds it.
glm::dvec3 pixelDirection(const SkyFrame& f, int column, int row) {
  double x = 2.0 * (column + 0.5) / f.image.width - 1.0, y = 1.0 - 2.0 * (row + 0.5) / f.image.height;
  glm::dvec4 n = f.inverseViewProjection * glm::dvec4(x, y, -1.0, 1.0), far = f.inverseViewProjection * glm::dvec4(x, y, 1.0, 1.0);
  return glm::normalize(glm::dvec3(far) / far.w - glm::dvec3(n) / n.w);
}

glm::dvec3 pixel(const Image& img, int column, int row) {
  const float* p = &img.rgba32f[(static_cast<size_t>(row) * img.width + column) * 4];
  return {p[0], p[1], p[2]};
}

glm::dvec3 sceneSun(double elevation, double azimuth) {
  SceneOptions o;
  o.sunElevationDegrees = static_cast<float>(elevation);
  o.sunAzimuthDegrees = static_cast<float>(azimuth);
  return glm::dvec3(sunDirection(o));
}

class SkyGpu : public ::testing::TestWithParam<GlApi> {};

// The footprint the sky pass measures at a pixel (its derivatives of the view direction):
// the chord to the neighbouring pixels' directions across the 2 x 2 quad the pixel shares
// (GL's coarse derivatives; image rows pair as window rows do for an even height).
double pixelFootprint(const SkyFrame& f, int column, int row) {
  int c = column & ~1, r = row & ~1;
  glm::dvec3 d = pixelDirection(f, c, r);
  return std::max(glm::length(pixelDirection(f, c + 1, r) - d), glm::length(pixelDirection(f, c, r + 1) - d));
}

// The reference's radiance over footprints within 3 % of the exact one, channel by channel
// (lowest, highest): the GPU takes the footprint from float derivatives of view directions
// it reconstructs from world positions 300 m out, measured up to 2.7 % off the exact chord
// there (0.2 % for a camera at the origin, as the environment cube's), and the disc's
// weight away from its centre moves with it.
std::pair<glm::dvec3, glm::dvec3> skyRadianceRange(glm::dvec3 d, glm::dvec3 sun, double footprint) {
  glm::dvec3 lowest(1e300), highest(-1e300);
  for (int k = -6; k <= 6; ++k) {
    glm::dvec3 l = skyRadiance(d, sun, footprint * (1.0 + 0.005 * k));
    lowest = glm::min(lowest, l);
    highest = glm::max(highest, l);
  }
  return {lowest, highest};
}

// Every pixel against the reference for its direction and footprint (the disc included:
// at these fields of view a pixel is 1 to 2 degrees across and the disc, band-limited to
// it, a smooth bump ~5 pixels wide), away from the horizon's step to the ground. The bound, 1e-3 of the pixel's largest channel:
// float32 rounds each of the ~60 operations of a pixel by 6e-8; GLSL sets no precision
// for atan, tan and pow, which llvmpipe computes with polynomial approximations good to
// ~1e-5 relative, and the model multiplies their errors by up to ~10 (exp(D gamma),
// the air mass near the horizon); and each RGB channel is a difference of XYZ terms as
// large as the luminance (coefficients up to 3.2), so a channel's error scales with the
// largest channel, not its own (a red sunset's blue is ~1e-3 of its red). Measured on
// llvmpipe: at most 3.8e-4 of the largest channel (the low sun's view).
TEST_P(SkyGpu, TheDrawnSkyIsTheReference) {
  auto ctx = EglContext::create(GetParam());
  struct View {
    double sunElevation, sunAzimuth;
    glm::dvec3 look;
    float fov;
  };
  const std::vector<View> views = {
      {30, 110, direction(40, 110), 100},   // the default sun, its circumsolar sky and the disc
      {30, 110, direction(40, 290), 100},   // the side away from the sun
      {5, 0, direction(10, 0), 60},         // low sun: the red disc and a bright horizon
      {60, 200, glm::dvec3(0, -1, 0), 120}, // straight down: the ground
      {-10, 110, glm::dvec3(0, 1, 0), 120}, // sun below the horizon: twilight, straight up
      {0, 110, direction(0, 110), 90},      // sun on the horizon, looking at the horizon
  };
  for (const View& v : views) {
    SCOPED_TRACE(testing::Message() << "sun " << v.sunElevation << "/" << v.sunAzimuth << ", look " << v.look.x << " "
                                    << v.look.y << " " << v.look.z);
    SkyFrame f = renderSky(*ctx, skyCamera(v.look, v.fov), v.sunElevation, v.sunAzimuth);
    glm::dvec3 sun = sceneSun(v.sunElevation, v.sunAzimuth);
    int compared = 0, failures = 0;
    for (int row = 0; row < f.image.height; ++row)
      for (int column = 0; column < f.image.width; ++column) {
        glm::dvec3 d = pixelDirection(f, column, row);
        glm::dvec3 gpu = pixel(f.image, column, row);
        ASSERT_TRUE(finiteNonNegative(gpu)) << column << ", " << row;
        if (std::abs(d.y) < 1e-4) continue;
        auto [low, high] = skyRadianceRange(d, sun, pixelFootprint(f, column, row));
        ++compared;
        double largest = std::max({low.r, low.g, low.b});
        for (int c = 0; c < 3; ++c) {
          if ((gpu[c] < low[c] - 1e-3 * largest || gpu[c] > high[c] + 1e-3 * largest) && failures++ < 5)
            ADD_FAILURE() << "pixel " << column << ", " << row << " channel " << c << ": gpu " << gpu[c] << ", reference "
                          << low[c] << " to " << high[c];
        }
      }
    EXPECT_GT(compared, 64 * 64 / 2);
  }
}

// Looking at the sun through a 2-degree field: the disc covers the middle pixels with the
// capped, air-mass-reddened radiance (times the band-limited disc's scale: 1.32 for these
// pixels of 0.06 deg). Without the disc the middle would be the circumsolar sky (~6
// units); without the transmittance r/b would be 1.
TEST_P(SkyGpu, TheSunDiscIsDrawnWithItsTransmittance) {
  auto ctx = EglContext::create(GetParam());
  for (double elevation : {5.0, 60.0}) {
    SCOPED_TRACE(elevation);
    glm::dvec3 sun = sceneSun(elevation, 0);
    SkyFrame f = renderSky(*ctx, skyCamera(sun, 2.0f), elevation, 0, 32);
    glm::dvec3 middle = pixel(f.image, 16, 16);
    auto [low, high] = skyRadianceRange(pixelDirection(f, 16, 16), sun, pixelFootprint(f, 16, 16));
    for (int c = 0; c < 3; ++c) {
      EXPECT_GE(middle[c], low[c] * (1.0 - 1e-3));
      EXPECT_LE(middle[c], high[c] * (1.0 + 1e-3));
    }
    glm::dvec3 corner = pixel(f.image, 0, 0);
    EXPECT_GT(luminance(middle), 1e3 * luminance(corner));
    if (elevation < 10) EXPECT_GT(middle.r / middle.b, 10.0);  // 30000 / 2262
    else EXPECT_GT(middle.r / middle.b, 1.2);                   // 30000 / 22460
  }
}

// The solid angle of the spherical triangle a, b, c (unit vectors), Van Oosterom and
// Strackee 1983: tan(omega / 2) = |a . (b x c)| / (1 + a.b + b.c + c.a).
double triangleSolidAngle(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
  return 2.0 * std::atan2(std::abs(glm::dot(a, glm::cross(b, c))), 1.0 + glm::dot(a, b) + glm::dot(b, c) + glm::dot(c, a));
}

// Pixels larger than the disc (1.04 deg, as a 128-texel cube face's 0.9 deg): the energy
// the GPU draws, the sum over pixels of (drawn - diffuse sky) times each pixel's solid
// angle, is the disc's, capped radiance times its solid angle, wherever the disc's centre
// falls among the pixel centres (on one, a quarter and half a pixel off in both axes).
// The bound: the band-limited disc's own sum over a grid, ~0.2 % (tests/runtime/
// sun_disc_test.cpp), and the sky's 1e-3 over the ~60 pixels summed.
TEST_P(SkyGpu, TheDrawnDiscsEnergyIsKeptWhereverItFallsAmongPixelCentres) {
  auto ctx = EglContext::create(GetParam());
  const int size = 64;
  const double fov = 60.0, elevation = 30.0, azimuth = 110.0;
  const glm::dvec3 sun = sceneSun(elevation, azimuth);
  const double pixelAngle = 2.0 * std::tan(fov / 2.0 * kDeg) / size;
  const glm::dvec3 right = glm::normalize(glm::cross(sun, glm::dvec3(0, 1, 0))), up = glm::cross(right, sun);
  for (double offset : {0.0, 0.25, 0.5}) {
    SCOPED_TRACE(offset);
    // The disc's centre `offset` pixels right of and above pixel (31, 31)'s centre.
    glm::dvec3 look = glm::normalize(sun + (0.5 + offset) * pixelAngle * right - (0.5 + offset) * pixelAngle * up);
    SkyFrame f = renderSky(*ctx, skyCamera(look, static_cast<float>(fov)), elevation, azimuth, size);
    glm::dvec3 energy(0.0);
    for (int row = 0; row < size; ++row)
      for (int column = 0; column < size; ++column) {
        glm::dvec3 d = pixelDirection(f, column, row);
        double footprint = pixelFootprint(f, column, row);
        if (glm::dot(d - sun, d - sun) > sunDiscShape(footprint).outer) continue;
        // The pixel's solid angle from its corners' directions.
        auto corner = [&](double dx, double dy) {
          double x = 2.0 * (column + 0.5 + dx) / size - 1.0, y = 1.0 - 2.0 * (row + 0.5 + dy) / size;
          glm::dvec4 n = f.inverseViewProjection * glm::dvec4(x, y, -1.0, 1.0), far = f.inverseViewProjection * glm::dvec4(x, y, 1.0, 1.0);
          return glm::normalize(glm::dvec3(far) / far.w - glm::dvec3(n) / n.w);
        };
        glm::dvec3 a = corner(-0.5, -0.5), b = corner(0.5, -0.5), c = corner(0.5, 0.5), e = corner(-0.5, 0.5);
        double omega = triangleSolidAngle(a, b, c) + triangleSolidAngle(a, c, e);
        energy += (pixel(f.image, column, row) - diffuseSkyRadiance(d, sun)) * omega;
      }
    glm::dvec3 expected = sunDiscRadiance(sun) * sunSolidAngle();
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(energy[c], expected[c], 4e-3 * expected[c]) << "channel " << c;
  }
}

// The opaque scene's light: a water shader (on a patch of open water seen from straight
// above) writes, per pixel, wg_sky_irradiance and wg_sun_irradiance for the normal the
// pixel's position names (an octahedral map of the sphere), against the reference. Both
// are sums of at most ~75 positive float terms (float32: ~1e-5 relative), each with the
// sky's own error (TheDrawnSkyIsTheReference): 1e-3 relative.
glm::dvec3 octahedralNormal(double u, double v) {
  glm::dvec2 f(2.0 * u - 1.0, 2.0 * v - 1.0);
  glm::dvec3 n(f.x, 1.0 - std::abs(f.x) - std::abs(f.y), f.y);
  if (n.y < 0.0) {
    double x = n.x, z = n.z;
    n.x = (1.0 - std::abs(z)) * (x >= 0.0 ? 1.0 : -1.0);
    n.z = (1.0 - std::abs(x)) * (z >= 0.0 ? 1.0 : -1.0);
  }
  return glm::normalize(n);
}

TEST_P(SkyGpu, TheOpaqueScenesLightIsTheReference) {
  auto ctx = EglContext::create(GetParam());
  std::vector<ShaderSource> shaders = test::handWaterShaders(ctx->isEs(), {});
  std::string header = ctx->isEs() ? "#version 300 es\nprecision highp float;\nprecision highp int;\n" : "#version 330 core\n";
  shaders[1].text = header + "uniform vec2 u_viewport_size;\nuniform vec3 u_sun_direction;\n" + skyGlsl() + R"glsl(
layout(location = 0) out vec4 o_color;
void main() {
  vec2 f = 2.0 * gl_FragCoord.xy / u_viewport_size - 1.0;
  vec3 n = vec3(f.x, 1.0 - abs(f.x) - abs(f.y), f.y);
  if (n.y < 0.0) n.xz = (1.0 - abs(n.zx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.z >= 0.0 ? 1.0 : -1.0);
  n = normalize(n);
  o_color = vec4(gl_FragCoord.x < 1.0 && gl_FragCoord.y < 1.0 ? wg_sun_irradiance(u_sun_direction)
                                                               : wg_sky_irradiance(n, u_sun_direction), 1.0);
}
)glsl";
  nlohmann::json m = test::handManifest({}, {});
  m["uniforms"].push_back({{"name", "u_sun_direction"}, {"type", "vec3"}, {"stages", {"fragment"}}, {"builtin", "sun_direction"}});
  for (double elevation : {45.0, 3.0, -4.0}) {
    SCOPED_TRACE(elevation);
    RenderSettings s = test::smallSettings();
    s.width = s.height = 32;
    s.floatColor = true;
    s.customCamera = Camera{{14.0f, 3.0f, 14.0f}, {14.0f, 0.0f, 14.0f}, 40.0f};
    s.scene.sunElevationDegrees = static_cast<float>(elevation);
    s.scene.sunAzimuthDegrees = 110;
    Renderer r(Manifest::fromJson(m), shaders, s, ctx->isEs());
    r.renderFrame();
    Image img = r.readRgba32f();
    glm::dvec3 sun = sceneSun(elevation, 110);
    // Rows are top to bottom; gl_FragCoord.y counts from the bottom.
    glm::dvec3 sunGpu = pixel(img, 0, img.height - 1), sunRef = sunIrradiance(sun);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sunGpu[c], sunRef[c], 1e-3 * sunRef[c] + 1e-9);
    int failures = 0;
    for (int row = 0; row < img.height; ++row)
      for (int column = 0; column < img.width; ++column) {
        if (column == 0 && row == img.height - 1) continue;
        glm::dvec3 n = octahedralNormal((column + 0.5) / img.width, (img.height - row - 0.5) / img.height);
        glm::dvec3 gpu = pixel(img, column, row), ref = skyIrradiance(n, sun);
        for (int c = 0; c < 3; ++c)
          if (std::abs(gpu[c] - ref[c]) > 1e-3 * ref[c] + 1e-6 && failures++ < 5)
            ADD_FAILURE() << "pixel " << column << ", " << row << " channel " << c << ": gpu " << gpu[c] << ", reference "
                          << ref[c];
      }
  }
}

INSTANTIATE_TEST_SUITE_P(Apis, SkyGpu, ::testing::Values(GlApi::DesktopGl45, GlApi::Es32),
                         [](const auto& info) { return std::string(info.param == GlApi::Es32 ? "es32" : "gl45"); });

}  // namespace
}  // namespace wg::rt
