// The spectral ocean's persistent foam (core/ocean_foam.h): the recurrence's properties,
// checked on the double reference (the GPU is held to it in
// tests/runtime/ocean_gpu_foam_test.cpp): foam grows only where J is below the threshold,
// stays in [0, 1], and where the growth stops it decays by exactly e^(-step / decay) per
// step; a replay's window is long enough that two replays of the same step from different
// starts differ by at most e^(-K step / decay); meaningless settings are errors naming
// their option.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "core/ocean_foam.h"
#include "core/ocean_settings.h"

namespace wg::ocean {
namespace {

// A storm on a small grid: whose surface folds (J < 0) at some texels.
OceanCascade stormCascade(double windSpeed = 25) {
  SpectrumSettings s;
  s.windSpeed = windSpeed;
  s.fetch = 500e3;
  CascadeSettings c;
  c.resolution = 64;
  c.tileLengths = {150};
  c.choppiness = 2.5;
  return initialCascade(s, c, 0);
}

TEST(OceanFoam, ACalmMakesNoFoam) {
  SpectrumSettings s;
  s.windSpeed = 0;
  CascadeSettings c;
  c.resolution = 64;
  c.tileLengths = {60};
  FoamSettings f;
  FoamMaps maps = replayFoam(initialCascade(s, c, 0), 1.0, f, 123);
  for (double v : maps.current) ASSERT_EQ(v, 0.0);
  for (double v : maps.next) ASSERT_EQ(v, 0.0);
}

TEST(OceanFoam, FoamGrowsWhereTheSurfaceFoldsAndStaysInTheUnitInterval) {
  FoamSettings f;
  const OceanCascade cascade = stormCascade();
  const std::int64_t n = 40;
  FoamMaps maps = replayFoam(cascade, 2.5, f, n);
  std::vector<double> j = oceanJacobian(cascade, static_cast<double>(n + 1) * f.step, 2.5);
  int grown = 0, partial = 0, folded = 0;
  for (size_t i = 0; i < j.size(); ++i) {
    ASSERT_GE(maps.next[i], 0.0);
    ASSERT_LE(maps.next[i], 1.0);
    if (j[i] < f.threshold) {
      // This step's growth alone: at least gain (threshold - J), or the clamp.
      ++folded;
      EXPECT_GE(maps.next[i], std::min(1.0, foamGain(f) * (f.threshold - j[i])) - 1e-15);
    }
    grown += maps.next[i] > 0;
    partial += maps.next[i] > 0 && maps.next[i] < 1;
  }
  // The sea reaches the regions the test names: folds, foam, foam below the clamp.
  EXPECT_GT(folded, 20);
  EXPECT_GT(partial, 20);
  EXPECT_LT(grown, static_cast<int>(j.size()));
}

// Where J stays at or above the threshold, foam only decays: by e^(-step / decay) exactly.
TEST(OceanFoam, FoamDecaysExponentiallyOnceTheFoldHasPassed) {
  FoamSettings f;
  const OceanCascade cascade = stormCascade();
  const double lambda = 2.5;
  const std::int64_t n = 40;
  FoamMaps a = replayFoam(cascade, lambda, f, n);
  std::vector<double> j = oceanJacobian(cascade, static_cast<double>(n + 1) * f.step, lambda);
  int decaying = 0;
  for (size_t i = 0; i < j.size(); ++i) {
    if (j[i] < f.threshold || a.current[i] == 0) continue;
    ++decaying;
    EXPECT_NEAR(a.next[i], a.current[i] * std::exp(-f.step / f.decay), 1e-15 * a.current[i]) << "texel " << i;
  }
  EXPECT_GT(decaying, 10);  // texels that had foam and whose fold has passed
}

// Two replays of one step that start K and K + 5 steps back: the older one's first five
// steps are forgotten to within keep^K (the recurrence is a contraction).
TEST(OceanFoam, TheReplayWindowForgetsOlderFoamToWithinItsDecay) {
  FoamSettings f;
  const OceanCascade cascade = stormCascade();
  const int k = historySteps(f);
  EXPECT_EQ(k, 75);  // 5 decay times of 1.5 s in steps of 0.1 s
  FoamMaps shorter = replayFoam(cascade, 2.5, f, 200);
  // The same recurrence started 5 steps earlier: continue replayFoam(195)'s state.
  FoamMaps early = replayFoam(cascade, 2.5, f, 195);
  std::vector<double> state = early.next;  // f_196 from a start at 196 - K
  for (std::int64_t m = 197; m <= 201; ++m) {
    std::vector<double> j = oceanJacobian(cascade, static_cast<double>(m) * f.step, 2.5);
    for (size_t i = 0; i < state.size(); ++i) state[i] = foamStep(state[i], j[i], foamKeep(f), foamGain(f), f.threshold);
  }
  double worst = 0;
  for (size_t i = 0; i < state.size(); ++i) worst = std::max(worst, std::abs(state[i] - shorter.next[i]));
  EXPECT_GT(worst, 0.0);  // the windows differ: the test compares two histories
  EXPECT_LE(worst, std::pow(foamKeep(f), k) + 1e-12);
}

TEST(OceanFoam, TheFrameBlendsTheTwoStepsAroundItsTime) {
  FoamSettings f;
  EXPECT_EQ(stepIndex(f, 4.25), 42);
  EXPECT_NEAR(foamFraction(f, 4.25), 0.5, 1e-9);
  EXPECT_EQ(stepIndex(f, std::numeric_limits<double>::quiet_NaN()), 0);
  EXPECT_EQ(foamFraction(f, std::numeric_limits<double>::infinity()), 0.0);
  EXPECT_EQ(stepIndex(f, -0.05), -1);  // before 0: still whole steps
  EXPECT_EQ(stepIndex(f, 1e6), 10000000);
}

TEST(OceanFoam, MeaninglessFoamSettingsAreErrorsNamingTheOption) {
  auto error = [](auto set) {
    FoamSettings f;
    set(f);
    auto e = validateFoam(f);
    return e ? e->parameter : std::string();
  };
  EXPECT_EQ(error([](FoamSettings&) {}), "");
  EXPECT_EQ(error([](FoamSettings& f) { f.step = 0; }), "foam_step");
  EXPECT_EQ(error([](FoamSettings& f) { f.step = std::nan(""); }), "foam_step");
  EXPECT_EQ(error([](FoamSettings& f) { f.decay = 0; }), "foam_decay");
  // A still frame would replay 5000 steps.
  EXPECT_EQ(error([](FoamSettings& f) { f.decay = 100; }), "foam_decay");
  EXPECT_EQ(error([](FoamSettings& f) { f.growth = -1; }), "foam_growth");
  EXPECT_EQ(error([](FoamSettings& f) { f.threshold = std::numeric_limits<double>::infinity(); }), "foam_threshold");
  EXPECT_EQ(error([](FoamSettings& f) { f.cascades = 0; }), "foam_cascades");
  OceanSettings s;
  s.foam.cascades = 2;
  EXPECT_TRUE(makesFoam(s, 0));
  EXPECT_FALSE(makesFoam(s, 1));  // one cascade only
}

// A still frame's replay is bounded in texel steps, (K + 1) x foam cascades x N^2: at the
// largest grid the budget admits 170 steps on three cascades and refuses 171 (an error at
// foam_decay naming the other settings), and counts only cascades that make foam.
TEST(OceanFoam, AStillFramesReplayIsWithinItsBudget) {
  OceanSettings s;
  s.cascades.resolution = 512;
  s.cascades.tileLengths = {400, 60, 9};
  s.foam.step = 0.1;
  s.foam.decay = 3.38;  // K = 169
  EXPECT_EQ(foamReplayTexelSteps(s), 170.0 * 3 * 512 * 512);
  EXPECT_LE(foamReplayTexelSteps(s), kFoamReplayBudget);
  EXPECT_FALSE(validateOcean(s).has_value());
  s.foam.decay = 3.4;  // K = 170
  ASSERT_TRUE(validateOcean(s).has_value());
  EXPECT_EQ(validateOcean(s)->parameter, "foam_decay");
  EXPECT_NE(validateOcean(s)->message.find("foam_cascades, fft_size or cascade_sizes"), std::string::npos);
  s.foam.cascades = 2;  // the third cascade makes none
  EXPECT_EQ(foamReplayTexelSteps(s), 171.0 * 2 * 512 * 512);
  EXPECT_FALSE(validateOcean(s).has_value());
  // The defaults, and the defaults at the largest grid, are within it.
  EXPECT_FALSE(validateOcean(OceanSettings{}).has_value());
  OceanSettings large;
  large.cascades.resolution = 512;
  large.cascades.tileLengths = {400, 60, 9, 2};
  EXPECT_FALSE(validateOcean(large).has_value());
}

}  // namespace
}  // namespace wg::ocean
