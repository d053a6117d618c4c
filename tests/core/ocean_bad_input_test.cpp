// The spectral ocean's bad input (issue 41): which values are errors, each naming its
// parameter, and which are documented extremes that give a finite sea (docs/ocean.md,
// "Limits"). An error is a value with no meaning (no fetch, no water, a grid the FFT
// cannot take, bands that would be counted twice or lost, a seed that would alias
// another); an extreme is a meaningful value far from where the spectra were fitted.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "core/ocean_fft_reference.h"
#include "ocean_test_support.h"

namespace wg::ocean {
namespace {

using namespace test_support;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string spectrumError(SpectrumSettings s) {
  auto e = validateSpectrum(s);
  return e ? e->parameter : "";
}

std::string cascadeError(CascadeSettings c) {
  auto e = validateCascades(c);
  return e ? e->parameter : "";
}

bool allFinite(const OceanFields& f) {
  for (const auto* field : {&f.height, &f.displacementX, &f.displacementZ, &f.slopeX, &f.slopeZ, &f.jacobian})
    for (double v : *field)
      if (!std::isfinite(v)) return false;
  return true;
}

double totalVariance(const OceanCascade& c) {
  double sum = 0;
  for (double v : c.binVariance) sum += v;
  return sum;
}

CascadeSettings smallGrid() {
  CascadeSettings c;
  c.resolution = 64;
  c.tileLengths = {800, 80};
  return c;
}

TEST(OceanBadInput, MeaninglessSpectrumSettingsAreErrorsNamingTheParameter) {
  SpectrumSettings ok;
  EXPECT_EQ(spectrumError(ok), "");
  auto with = [&](auto set) {
    SpectrumSettings s = ok;
    set(s);
    return spectrumError(s);
  };
  for (double u : {-1.0, 100.5, kNaN, kInf}) EXPECT_EQ(with([&](auto& s) { s.windSpeed = u; }), "wind_speed") << u;
  EXPECT_EQ(with([](auto& s) { s.windDirection = kInf; }), "wind_direction");
  for (double f : {0.0, -10.0, kNaN}) EXPECT_EQ(with([&](auto& s) { s.fetch = f; }), "fetch") << f;
  for (double d : {0.0, -3.0, kNaN}) EXPECT_EQ(with([&](auto& s) { s.depth = d; }), "depth") << d;
  for (double g : {0.5, 21.0, kNaN}) EXPECT_EQ(with([&](auto& s) { s.gamma = g; }), "gamma") << g;
  EXPECT_EQ(with([](auto& s) { s.phillipsAmplitude = -1; }), "phillips_amplitude");
  EXPECT_EQ(with([](auto& s) { s.phillipsSmallWave = kNaN; }), "phillips_small_wave");
  EXPECT_EQ(with([](auto& s) { s.swell.height = -0.1; }), "swell_height");
  EXPECT_EQ(with([](auto& s) { s.swell.period = 0; }), "swell_period");
  EXPECT_EQ(with([](auto& s) { s.swell.direction = kNaN; }), "swell_direction");
  EXPECT_EQ(with([](auto& s) { s.swell.spread = 1e4; }), "swell_spread");
  // The messages say the value and the range.
  SpectrumSettings s = ok;
  s.fetch = 0;
  EXPECT_EQ(validateSpectrum(s)->message, "fetch 0 m must be greater than 0 (the sea needs open water to grow)");
}

TEST(OceanBadInput, MeaninglessCascadeSettingsAreErrorsNamingTheParameter) {
  CascadeSettings ok;
  EXPECT_EQ(cascadeError(ok), "");
  auto with = [&](auto set) {
    CascadeSettings c = ok;
    set(c);
    return cascadeError(c);
  };
  for (int n : {0, -256, 32, 100, 255, 1024}) EXPECT_EQ(with([&](auto& c) { c.resolution = n; }), "resolution") << n;
  for (int n : {64, 128, 512}) EXPECT_EQ(with([&](auto& c) { c.resolution = n; }), "") << n;
  EXPECT_EQ(with([](auto& c) { c.tileLengths = {}; }), "tile_lengths");
  EXPECT_EQ(with([](auto& c) { c.tileLengths = {1000, 500, 250, 125, 60}; }), "tile_lengths");
  EXPECT_EQ(with([](auto& c) { c.tileLengths = {0}; }), "tile_lengths");
  EXPECT_EQ(with([](auto& c) { c.tileLengths = {kInf}; }), "tile_lengths");
  // Out of order, repeated, and so far apart that the wavenumbers between are lost at the
  // smallest resolution, 64^2, whatever the resolution (the finer tile at most 31 times
  // shorter: the bands do not move with the resolution).
  CascadeSettings c = ok;
  c.tileLengths = {250, 1000};
  EXPECT_EQ(validateCascades(c)->message,
            "cascade 1: tile length 1000 m is longer than cascade 0's 250 m: list the cascades from the longest tile to "
            "the shortest");
  c.tileLengths = {1000, 1000};
  EXPECT_EQ(validateCascades(c)->parameter, "tile_lengths");
  c.tileLengths = {1000, 1000.0 / 31};
  EXPECT_EQ(validateCascades(c)->parameter, "tile_lengths");
  c.tileLengths = {1000, 1000.0 / 30.9};
  EXPECT_FALSE(validateCascades(c));
  for (double l : {-0.1, 4.5, kNaN}) EXPECT_EQ(with([&](auto& c) { c.choppiness = l; }), "choppiness") << l;
  // A seed names one of 2^32 seas; one outside would alias another, so it is refused.
  for (std::int64_t seed : {std::int64_t{-1}, std::int64_t{1} << 32, std::int64_t{1} << 40})
    EXPECT_EQ(with([&](auto& c) { c.seed = seed; }), "seed") << seed;
  EXPECT_EQ(with([](auto& c) { c.seed = 4294967295; }), "");
  // The reference itself refuses what validation refuses.
  c.tileLengths = {250, 1000};
  EXPECT_THROW(initialCascade(SpectrumSettings{}, c, 0), std::invalid_argument);
  EXPECT_THROW(initialCascade(SpectrumSettings{}, ok, 1), std::invalid_argument);
}

TEST(OceanBadInput, ACalmIsAFlatSeaNotNaN) {
  for (SpectrumModel m : {SpectrumModel::Phillips, SpectrumModel::PiersonMoskowitz, SpectrumModel::Jonswap,
                          SpectrumModel::Tma}) {
    SpectrumSettings s;
    s.model = m;
    s.windSpeed = 0;
    s.depth = 20;
    CascadeSettings c = smallGrid();
    for (int i = 0; i < 2; ++i) {
      OceanFields f = oceanFields(initialCascade(s, c, i), 1e6, 1.0);
      for (size_t j = 0; j < f.height.size(); ++j) {
        ASSERT_EQ(f.height[j], 0.0);
        ASSERT_EQ(f.jacobian[j], 1.0);
        ASSERT_EQ(f.slopeX[j], 0.0);
      }
    }
    // A breath of wind is still finite.
    s.windSpeed = 1e-300;
    EXPECT_TRUE(allFinite(oceanFields(initialCascade(s, c, 0), 0, 1)));
  }
}

TEST(OceanBadInput, AGaleIsFiniteAndHoldsNoMoreThanItsSpectrum) {
  // U10 = 40 m/s: a Pierson-Moskowitz sea of Hs = 0.22 U10^2 / g ~ 36 m whose peak
  // wavelength (~1.4 km) is longer than the 800 m tile; what the tile cannot hold is lost,
  // nothing is invented, and every field stays finite at full choppiness.
  SpectrumSettings s;
  s.windSpeed = 40;
  for (SpectrumModel m : {SpectrumModel::PiersonMoskowitz, SpectrumModel::Jonswap, SpectrumModel::Phillips}) {
    s.model = m;
    CascadeSettings c = smallGrid();
    c.choppiness = kMaxChoppiness;
    double held = 0;
    for (int i = 0; i < 2; ++i) {
      OceanCascade cascade = initialCascade(s, c, i);
      held += totalVariance(cascade);
      EXPECT_TRUE(allFinite(oceanFields(cascade, 1e6, c.choppiness)));
    }
    if (m == SpectrumModel::PiersonMoskowitz) {
      double u = 1.026 * 40;
      EXPECT_LT(held, 0.0081 * std::pow(u, 4) / (4 * 0.74 * 9.81 * 9.81));
    }
    EXPECT_GT(held, 0.0);
  }
}

TEST(OceanBadInput, WaterFarShallowerThanAWaveIsFiniteAndNearlyStill) {
  // depth -> 0: omega -> k sqrt(g d) -> 0, and TMA's factor -> (omega_h)^2 / 2 -> 0.
  SpectrumSettings deep;
  double deepVariance = totalVariance(initialCascade(deep, smallGrid(), 0));
  for (SpectrumModel m : {SpectrumModel::Tma, SpectrumModel::Jonswap, SpectrumModel::PiersonMoskowitz}) {
    SpectrumSettings s;
    s.model = m;
    s.depth = 1e-6;
    OceanCascade c = initialCascade(s, smallGrid(), 0);
    EXPECT_TRUE(allFinite(oceanFields(c, 1e6, 1.0)));
    EXPECT_LT(totalVariance(c), 1e-12 * deepVariance) << static_cast<int>(m);
    for (std::uint32_t n : c.frequency) ASSERT_LT(angularFrequencyOf(n), 0.02);
  }
  // The smallest depth a double holds: k d rounds to 0, where 2kd / sinh(2kd) would be 0/0.
  const double thinnest = std::numeric_limits<double>::denorm_min();
  EXPECT_TRUE(std::isfinite(groupVelocity(0.01, thinnest)));
  EXPECT_TRUE(std::isfinite(tmaDepthFactor(0.01, thinnest)));
  SpectrumSettings film;
  film.model = SpectrumModel::Tma;
  film.depth = thinnest;
  EXPECT_TRUE(allFinite(oceanFields(initialCascade(film, smallGrid(), 0), 1e6, 1.0)));
}

TEST(OceanBadInput, FetchExtremes) {
  // A metre of fetch: a finite sea of ripples (omega_p = 47 rad/s, 3 cm long) that a
  // half-metre tile holds. An unbounded fetch: the fully developed sea, the same as any
  // fetch past gF/U^2 = 1.7e4.
  SpectrumSettings s;
  s.fetch = 1;
  CascadeSettings tiny = smallGrid();
  tiny.tileLengths = {0.5};
  OceanCascade ripples = initialCascade(s, tiny, 0);
  EXPECT_TRUE(allFinite(oceanFields(ripples, 0, 1)));
  EXPECT_GT(totalVariance(ripples), 0.0);
  s.fetch = kInf;
  OceanCascade unbounded = initialCascade(s, smallGrid(), 0);
  s.fetch = 1e12;
  EXPECT_EQ(unbounded.h0, initialCascade(s, smallGrid(), 0).h0);
}

TEST(OceanBadInput, TimesAndTilesAtTheirEnds) {
  // The loop fraction at the ends of time: negative times count back from a whole loop,
  // and a clock that is not finite stands at 0.
  EXPECT_EQ(loopFraction(0.0), 0u);
  EXPECT_EQ(loopFraction(kLoopPeriod / 2), 2147483648u);
  EXPECT_EQ(loopFraction(-kLoopPeriod / 4), 3221225472u);
  EXPECT_EQ(loopFraction(1e300), 0u);
  for (double t : {kInf, -kInf, kNaN}) EXPECT_EQ(loopFraction(t), 0u) << t;
  // A tile of ten nanometres: its fastest bins exceed the largest frequency index, which
  // they keep; the fields stay finite.
  SpectrumSettings s;
  s.fetch = 1e-3;
  CascadeSettings c = smallGrid();
  c.tileLengths = {1e-8};
  OceanCascade tiny = initialCascade(s, c, 0);
  EXPECT_EQ(tiny.frequency[static_cast<size_t>(31) * 64 + 31], 4294967295u);
  EXPECT_TRUE(allFinite(oceanFields(tiny, 1e6, 1.0)));
}

}  // namespace
}  // namespace wg::ocean
