// The tuner's search on made-up measurements: which configuration it chooses, in which
// order it lowers knobs, how ties break, and that NaN, an unmeetable budget and a failed
// verification are handled. No renderer: the numbers are the test's.
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

#include <gtest/gtest.h>

#include "accuracy/tune_search.h"

namespace wg::accuracy {
namespace {

// Measurements from two functions of the configuration.
class FakeMeasurements : public TuneMeasurements {
 public:
  std::function<TuneError(const TuneConfig&)> errorOf;
  std::function<TuneCost(const TuneConfig&)> costOf;
  std::function<TuneError(const TuneConfig&)> verifyOf;  // default: errorOf
  int errors = 0, costs = 0;

  TuneError error(const TuneConfig& c) override { return ++errors, errorOf(c); }
  std::vector<TuneCost> cost(const std::vector<TuneConfig>& configs) override {
    ++costs;
    std::vector<TuneCost> out;
    for (const auto& c : configs) out.push_back(costOf(c));
    return out;
  }
  TuneError verify(const TuneConfig& c) override { return verifyOf ? verifyOf(c) : errorOf(c); }
};

TuneError psnr(double db, double maxAbs = 0.01) { return {db, maxAbs, true, "above t=1"}; }

std::vector<TuneKnob> twoKnobs() {
  return {{"detail", "octaves", {1, 2, 3}}, {"f", "model", {"power", "schlick", "exact"}}};
}

std::vector<std::string> pathOf(const TuneResult& r) {
  std::vector<std::string> p;
  for (size_t i = 1; i < r.path.size(); ++i) p.push_back(r.path[i].knob + "=" + r.path[i].level);
  return p;
}

TuneBudget minPsnr(double db) {
  TuneBudget b;
  b.minPsnr = db;
  return b;
}

// Octaves are nearly free in error; any Fresnel model but the exact one is far off.
TEST(TuneSearch, LowersTheFreeKnobAndKeepsTheCostlyOne) {
  FakeMeasurements m;
  m.errorOf = [](const TuneConfig& c) {
    if (c[1] < 2) return psnr(30);
    return c[0] == 2 ? psnr(INFINITY, 0) : psnr(70 - 5 * (1 - c[0]));
  };
  m.costOf = [](const TuneConfig& c) { return TuneCost{10.0 + 3 * c[0] + 5 * c[1], 100 + 10 * c[0] + 20 * c[1]}; };
  TuneResult r = tuneSearch(twoKnobs(), minPsnr(45), m);
  ASSERT_TRUE(r.found) << r.why;
  EXPECT_EQ(pathOf(r), (std::vector<std::string>{"detail.octaves=2", "detail.octaves=1"}));
  EXPECT_EQ(r.chosen().config, (TuneConfig{0, 2}));
  EXPECT_EQ(r.verified.worstPsnr, 65);
  // Tried: the reference, round 1 (octaves, model), round 2 (octaves, model), round 3 (model).
  EXPECT_EQ(r.tried.size(), 6u);
  EXPECT_FALSE(r.tried[2].meetsBudget);  // model=schlick from the reference
}

// Both knobs meet the budget; the one with less error per saved ms goes first, whatever
// the knobs' order.
TEST(TuneSearch, TakesTheLeastErrorPerSavedCostFirst) {
  FakeMeasurements m;
  // Usage of a 40 dB budget: octaves cost 1e-5 MSE per level and save 1 ms; the model
  // costs 1e-5 per level and saves 4 ms.
  m.errorOf = [](const TuneConfig& c) {
    double mse = 1e-5 * ((2 - c[0]) + (2 - c[1]));
    return mse == 0 ? psnr(INFINITY, 0) : psnr(10 * std::log10(1 / mse));
  };
  m.costOf = [](const TuneConfig& c) { return TuneCost{10.0 + 1 * c[0] + 4 * c[1], 100}; };
  TuneResult r = tuneSearch(twoKnobs(), minPsnr(40), m);
  ASSERT_TRUE(r.found) << r.why;
  // 40 dB allows MSE 1e-4: all four steps fit; the model's two come first.
  EXPECT_EQ(pathOf(r), (std::vector<std::string>{"f.model=schlick", "f.model=power", "detail.octaves=2", "detail.octaves=1"}));
}

// Equal error and equal time saved: fewer SPIR-V instructions first, then the knob's name;
// two runs on the same measurements take the same path.
TEST(TuneSearch, TiesBreakBySpirvThenNameAndRepeat) {
  std::vector<TuneKnob> knobs{{"z", "bypass", {true, false}}, {"b", "bypass", {true, false}}, {"a", "bypass", {true, false}}};
  FakeMeasurements m;
  m.errorOf = [](const TuneConfig& c) { return c == TuneConfig{1, 1, 1} ? psnr(INFINITY, 0) : psnr(60); };
  // Switching z or b off leaves 240 instructions, a 250: b first (fewer instructions than
  // a, and of z and b, the first by name), then z (180 against a's 190), then a.
  m.costOf = [](const TuneConfig& c) {
    return TuneCost{3.0 + c[0] + c[1] + c[2], 300 - 60 * (1 - c[0]) - 60 * (1 - c[1]) - 50 * (1 - c[2])};
  };
  TuneResult first = tuneSearch(knobs, minPsnr(45), m);
  TuneResult second = tuneSearch(knobs, minPsnr(45), m);
  EXPECT_EQ(pathOf(first), (std::vector<std::string>{"b.bypass=true", "z.bypass=true", "a.bypass=true"}));
  EXPECT_EQ(pathOf(first), pathOf(second));
  ASSERT_EQ(first.tried.size(), second.tried.size());
  for (size_t i = 0; i < first.tried.size(); ++i) EXPECT_EQ(first.tried[i].label, second.tried[i].label);
}

// Repeats of a configuration costing `base` ms/MP, one per interleaved repeat: the machine's
// load in each repeat (shared by every configuration timed in it) times the base.
TuneCost timed(double base, int spirv, std::vector<double> load) {
  TuneCost c{0, spirv, {}};
  for (double l : load) c.repeats.push_back(base * l);
  std::vector<double> sorted = c.repeats;
  std::sort(sorted.begin(), sorted.end());
  c.msPerMegapixel = sorted[sorted.size() / 2];
  return c;
}

// A lower median the paired repeats do not bear out is noise: the candidate is taken
// neither for time nor, when it is slower in every repeat, for fewer instructions. The
// saving every repeat shows is taken.
TEST(TuneSearch, ASavingTheRepeatsDoNotShowIsNotTaken) {
  const std::vector<double> load{1.0, 1.3, 0.9, 1.1, 1.0};
  TuneCost reference = timed(100, 500, load);
  // 'noise': lower median (97 against 100), but faster in only 3 of the 5 repeats.
  TuneCost noise{97, 500, {99, 120, 85, 111, 97}};
  EXPECT_EQ(timeSaved(noise, reference), 0);
  // 'real': 10 % cheaper in every repeat.
  TuneCost real = timed(90, 500, load);
  EXPECT_DOUBLE_EQ(timeSaved(real, reference), 10);
  EXPECT_EQ(timeSaved(reference, real), 0) << "a slower candidate saves nothing";
  // A one-sided sign test at 10 %: 8 of 10 faster counts, 7 of 10 does not.
  TuneCost ten{100, 1, {100, 100, 100, 100, 100, 100, 100, 100, 100, 100}};
  TuneCost eight{95, 1, {95, 95, 95, 95, 95, 95, 95, 95, 101, 101}};
  TuneCost seven{95, 1, {95, 95, 95, 95, 95, 95, 95, 101, 101, 101}};
  EXPECT_DOUBLE_EQ(timeSaved(eight, ten), 5);
  EXPECT_EQ(timeSaved(seven, ten), 0);
  // Three repeats cannot show a difference (all three faster by chance: 1 in 8).
  EXPECT_EQ(timeSaved(TuneCost{90, 1, {90, 90, 90}}, TuneCost{100, 1, {100, 100, 100}}), 0);
  EXPECT_DOUBLE_EQ(timeSaved(TuneCost{90, 1, {90, 90, 90, 90}}, TuneCost{100, 1, {100, 100, 100, 100}}), 10);
  std::vector<size_t> needed;
  for (size_t n : {1, 3, 4, 5, 6, 7, 9, 10, 20}) needed.push_back(repeatsToShowASaving(n));
  EXPECT_EQ(needed, (std::vector<size_t>{2, 4, 4, 5, 6, 6, 7, 8, 14}));
  // A stricter level asks for more: at 1.4 % all 9 of 9 (8 of 9 by chance: 2 %).
  EXPECT_EQ(repeatsToShowASaving(9, 0.1 / 7), 9u);
  // Repeats that are not paired (another count) show nothing.
  EXPECT_EQ(timeSaved(TuneCost{90, 1, {90, 90, 90, 90, 90}}, TuneCost{100, 1, {100, 100, 100, 100}}), 0);

  std::vector<TuneKnob> knobs{{"a", "level", {0, 1}}, {"b", "level", {0, 1}}};
  FakeMeasurements m;
  m.errorOf = [](const TuneConfig& c) { return c == TuneConfig{1, 1} ? psnr(INFINITY, 0) : psnr(60); };
  // a: a lower median, not borne out by the repeats, same instructions. b: 20 fewer
  // instructions, but slower in every repeat. Neither is a saving.
  m.costOf = [&](const TuneConfig& c) {
    if (c[0] == 0) return noise;
    if (c[1] == 0) return timed(110, 480, load);
    return reference;
  };
  TuneResult r = tuneSearch(knobs, minPsnr(45), m);
  EXPECT_FALSE(r.found) << pathOf(r).front();
  // With b 10 % faster in every repeat, b is taken.
  m.costOf = [&](const TuneConfig& c) {
    if (c[0] == 0) return noise;
    if (c[1] == 0) return timed(90, 480, load);
    return reference;
  };
  r = tuneSearch(knobs, minPsnr(45), m);
  ASSERT_TRUE(r.found) << r.why;
  EXPECT_EQ(pathOf(r), (std::vector<std::string>{"b.level=0"}));
}

TEST(TuneSearch, ACandidateWithNaNIsNeverTaken) {
  FakeMeasurements m;
  m.errorOf = [](const TuneConfig& c) {
    if (c[0] < 2) return TuneError{INFINITY, 0, false, "grazing t=20"};  // fewer octaves: NaN somewhere
    return c[1] == 2 ? psnr(INFINITY, 0) : psnr(50);
  };
  m.costOf = [](const TuneConfig& c) { return TuneCost{1.0 + 100 * c[0] + c[1], 100}; };
  TuneResult r = tuneSearch(twoKnobs(), minPsnr(45), m);
  ASSERT_TRUE(r.found) << r.why;
  EXPECT_EQ(pathOf(r), (std::vector<std::string>{"f.model=schlick", "f.model=power"}));
}

TEST(TuneSearch, ABudgetNothingMeetsIsNotFoundAndSaysSo) {
  FakeMeasurements m;
  m.errorOf = [](const TuneConfig& c) { return c == TuneConfig{2, 2} ? psnr(INFINITY, 0) : psnr(80, 1e-4); };
  m.costOf = [](const TuneConfig& c) { return TuneCost{1.0 + c[0] + c[1], 100}; };
  TuneBudget exact;
  exact.maxAbsError = 0;
  TuneResult r = tuneSearch(twoKnobs(), exact, m);
  EXPECT_FALSE(r.found);
  EXPECT_EQ(r.path.size(), 1u);
  EXPECT_NE(r.why.find("no configuration cheaper than the reference meets the budget"), std::string::npos) << r.why;
  // The reference itself, rendered again, differing from its first render (a noisy target).
  m.errorOf = [](const TuneConfig&) { return psnr(90, 1e-5); };
  r = tuneSearch(twoKnobs(), exact, m);
  EXPECT_FALSE(r.found);
  EXPECT_NE(r.why.find("even the reference"), std::string::npos) << r.why;
}

TEST(TuneSearch, AStepThatFailsVerificationIsUndone) {
  FakeMeasurements m;
  m.errorOf = [](const TuneConfig& c) { return c == TuneConfig{2, 2} ? psnr(INFINITY, 0) : psnr(60); };
  m.costOf = [](const TuneConfig& c) { return TuneCost{1.0 + c[0] + 2 * c[1], 100}; };
  // Rendered again, the lowest configuration comes out worse than it measured.
  m.verifyOf = [](const TuneConfig& c) { return c == TuneConfig{0, 0} ? psnr(40) : psnr(60); };
  TuneResult r = tuneSearch(twoKnobs(), minPsnr(45), m);
  ASSERT_TRUE(r.found) << r.why;
  // Path: model=schlick (saves more), then the zero-error ties by name: octaves, octaves, model.
  EXPECT_EQ(r.chosen().config, (TuneConfig{0, 1}));
  EXPECT_EQ(r.verified.worstPsnr, 60);
}

}  // namespace
}  // namespace wg::accuracy
