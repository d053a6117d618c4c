// The foam nodes: edge_foam (depth masks of seeds 002/003, the cut-off with equal edges,
// range, monotone in depth, periodic at t = 1e6 s), crest_foam (the top-down water plan's values written out
// by hand, range, seamless drift), coastal_foam (the deferred water article's amount and specular dimming) and
// shore_waves (the stylized water shader's formula by hand, huge time).
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "nodes/foam_caustics_reference.h"
#include "nodes/texture_source.h"
#include "node_eval.h"

namespace wg {
namespace {

using test::atTime;
using test::runNode;

Value pos(double x, double z) { return Value::vector({x, 0.0, z}); }

TEST(EdgeFoam, MasksByHand) {
  // The advanced shaders tutorial: 1 - smoothstep(0, 0.5, depth): 0.5 at 0.25, 1 at 0, 0 from 0.5 on.
  EXPECT_NEAR(nodes::edgeFoamMask(true, 0.25, 0.5), 0.5, 1e-15);
  EXPECT_NEAR(nodes::edgeFoamMask(true, 0.125, 0.5), 1 - (0.0625 * (3 - 0.5)), 1e-15);
  EXPECT_EQ(nodes::edgeFoamMask(true, 0.0, 0.5), 1.0);
  EXPECT_EQ(nodes::edgeFoamMask(true, 0.7, 0.5), 0.0);
  // The stylized water shader: 1 - saturate(depth / distance).
  EXPECT_NEAR(nodes::edgeFoamMask(false, 0.25, 0.5), 0.5, 1e-15);
  EXPECT_EQ(nodes::edgeFoamMask(false, -1.0, 0.5), 1.0);
  EXPECT_EQ(nodes::edgeFoamMask(false, 0.2, 0.0), 0.0);  // width floored, no division by zero
  // Zero width, smooth: equal edges, a step at 0.
  EXPECT_EQ(nodes::edgeFoamMask(true, -1e-9, 0.0), 1.0);
  EXPECT_EQ(nodes::edgeFoamMask(true, 1e-9, 0.0), 0.0);
}

TEST(EdgeFoam, EqualCutoffEdgesGiveTheSeedStep) {
  // softness 0: smoothstep(c, c, x) is the stylized water shader's step(c, x): 0 below, 1 at and above.
  EXPECT_EQ(nodes::edgeFoamCut(0.5, 0.49, 0.25, 0.0, 1.0), 0.0);
  EXPECT_EQ(nodes::edgeFoamCut(0.5, 0.5, 0.25, 0.0, 1.0), 1.0);
  EXPECT_EQ(nodes::edgeFoamCut(0.5, 1.0, 0.25, 0.0, 0.6), 0.6);
  EXPECT_NEAR(nodes::edgeFoamCut(0.5, 0.55, 0.25, 0.1, 1.0), 0.15625, 1e-15);  // t = 0.25: 0.0625 * 2.5
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> d(-0.5, 2.0), xz(-500, 500);
  for (int i = 0; i < 1500; ++i) {
    auto r = runNode("edge_foam", {{"depth", Value::scalar(d(rng))}, {"position", pos(xz(rng), xz(rng))}});
    double f = r.first();
    ASSERT_TRUE(f == 0.0 || f == 1.0) << f;
  }
}

TEST(EdgeFoam, InUnitRangeAndNonIncreasingWithDepth) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> xz(-300, 300);
  for (const char* mask : {"smooth", "linear"})
    for (int i = 0; i < 200; ++i) {
      Value p = pos(xz(rng), xz(rng));
      double prev = 2.0;
      for (double depth = -0.5; depth <= 1.0; depth += 0.05) {
        auto r = runNode("edge_foam", {{"depth", Value::scalar(depth)}, {"position", p}, {"softness", Value::scalar(0.1)},
                                        {"strength", Value::scalar(1.5)}},
                          {{"mask", mask}});
        double f = r.first();
        ASSERT_GE(f, 0.0);
        ASSERT_LE(f, 1.0);
        ASSERT_LE(f, prev + 1e-15);
        prev = f;
      }
      // No foam on deep water (cutoff 0.25 > 0).
      EXPECT_EQ(runNode("edge_foam", {{"depth", Value::scalar(50)}, {"position", p}}, {{"mask", mask}}).first(), 0.0);
    }
}

TEST(EdgeFoam, MatchesTheTwoLayerFormulaAndWrapsAtHugeTime) {
  auto tex = generateBuiltinTexture("foam");
  ASSERT_TRUE(tex);
  double x = 12.3, z = -45.6, depth = 0.1, t = 1e6, s = 0.05;
  double o1 = std::fmod(s * t, 1.0), o2 = std::fmod(0.5 * s * t, 1.0);
  double a = tex->sample(x * 0.1 + o1, z * 0.1 + o2)[0];
  double b = tex->sample(x * 0.08 - o2, z * 0.08 + o1)[0];
  double mask = 1 - 0.04 * (3 - 0.4);  // 1 - smoothstep(0, 0.5, 0.1): t = 0.2
  double texMask = 0.5 * (a + b) * mask;
  double tt = std::min(std::max((texMask - 0.25) / 0.2, 0.0), 1.0);
  double expected = tt * tt * (3 - 2 * tt);
  auto r = runNode("edge_foam", {{"depth", Value::scalar(depth)}, {"position", pos(x, z)}, {"softness", Value::scalar(0.2)}},
                    {}, atTime(t));
  EXPECT_NEAR(r.first(), expected, 1e-9);
  // Speed 0.05: both layers repeat after 40 s, at any time.
  auto r2 = runNode("edge_foam", {{"depth", Value::scalar(depth)}, {"position", pos(x, z)}, {"softness", Value::scalar(0.2)}},
                     {}, atTime(t + 40));
  EXPECT_NEAR(r2.first(), r.first(), 1e-9);
}

TEST(CrestFoam, SeedValuesByHand) {
  // coverage 1.2 puts the noise threshold at -0.2: the mask is 1 everywhere.
  auto env = atTime(0);
  Value up = Value::vector({0, 1, 0});
  // A crest: height 1 > threshold 0.65 + 0.15, so base = 1; foam = 0.7^(1/3).
  auto crest = runNode("crest_foam", {{"height", Value::scalar(1)}, {"normal", up}, {"coverage", Value::scalar(1.2)}}, {}, env);
  EXPECT_NEAR(crest.first(), std::cbrt(0.7), 1e-12);
  // A 60 degree slope at height 0: slope 0.866 > 0.7, base = 0.4; foam = 0.28^(1/3).
  Value steep = Value::vector({std::sin(M_PI / 3), std::cos(M_PI / 3), 0});
  auto slope = runNode("crest_foam", {{"height", Value::scalar(0)}, {"normal", steep}, {"coverage", Value::scalar(1.2)}}, {}, env);
  EXPECT_NEAR(slope.first(), std::cbrt(0.28), 1e-12);
  // Halfway up the height ramp: smoothstep = 0.5; sharpness 1: foam = 0.5 * 0.7.
  auto mid = runNode("crest_foam", {{"height", Value::scalar(0.725)}, {"normal", up}, {"coverage", Value::scalar(1.2)},
                                     {"sharpness", Value::scalar(1)}}, {}, env);
  EXPECT_NEAR(mid.first(), 0.35, 1e-12);
  // Coverage 0: the mask needs noise above 0.9..1.1, which the normalised noise (< 1) never
  // fully reaches; flat low water has no foam at all.
  auto none = runNode("crest_foam", {{"height", Value::scalar(0)}, {"normal", up}}, {}, env);
  EXPECT_EQ(none.first(), 0.0);
}

TEST(CrestFoam, InRangeAndSeamlessAtHugeTime) {
  std::mt19937 rng(37);
  std::uniform_real_distribution<double> h(-1, 2), xz(-1e4, 1e4), n(-1, 1);
  for (int i = 0; i < 500; ++i) {
    std::vector<std::pair<std::string, Value>> in = {{"height", Value::scalar(h(rng))},
                                                     {"normal", Value::vector({n(rng), n(rng), n(rng)})},
                                                     {"position", pos(xz(rng), xz(rng))}};
    double f = runNode("crest_foam", in, {}, atTime(1e6)).first();
    ASSERT_TRUE(std::isfinite(f));
    ASSERT_GE(f, 0.0);
    ASSERT_LE(f, 1.0);
    // The drifts (0.3 and 0.2 per second on a 256-cell lattice) both return after 2560 s.
    double f2 = runNode("crest_foam", in, {}, atTime(1e6 + 2560)).first();
    ASSERT_NEAR(f, f2, 1e-7);
  }
  // The drift moves the patches: a moment later the foam differs somewhere.
  int moved = 0;
  for (int i = 0; i < 50; ++i) {
    std::vector<std::pair<std::string, Value>> in = {{"height", Value::scalar(1)}, {"position", pos(i * 3.1, -i * 1.7)}};
    moved += runNode("crest_foam", in, {}, atTime(100)).first() != runNode("crest_foam", in, {}, atTime(103)).first();
  }
  EXPECT_GT(moved, 10);
}

TEST(CoastalFoam, AmountAndSpecularDimmingByHand) {
  EXPECT_NEAR(nodes::coastalFoamAmount(0.25, 1.0, 1.0, 0.0), 0.75, 1e-15);
  EXPECT_EQ(nodes::coastalFoamAmount(2.0, 1.0, 1.0, 0.0), 0.0);
  EXPECT_EQ(nodes::coastalFoamAmount(2.0, 1.0, 1.0, 0.4), 0.4);  // the crest term (the deferred water article's max)
  EXPECT_EQ(nodes::coastalFoamAmount(-1.0, 1.0, 0.8, 0.0), 0.8);
  EXPECT_EQ(nodes::coastalFoamAmount(3e38, 0.0, 0.0, 0.0), 0.0);
  EXPECT_NEAR(nodes::coastalFoamSpecular(0.5, 1.0, true), 0.125, 1e-15);  // (1 - 0.5)^3
  EXPECT_NEAR(nodes::coastalFoamSpecular(0.5, 1.0, false), 0.5, 1e-15);
  EXPECT_EQ(nodes::coastalFoamSpecular(0.9, 2.0, true), 0.0);
  EXPECT_EQ(nodes::coastalFoamSpecular(0.9, -2.0, false), 1.0);
}

TEST(CoastalFoam, NodeMatchesTheSeedFormula) {
  auto tex = generateBuiltinTexture("foam");
  ASSERT_TRUE(tex);
  Value n = Value::vector({0.2, 0.95, -0.3});
  double x = 7.5, z = 3.25, depth = 0.3;
  double u = 0.1 * x + 0.5 + 0.05 * 0.2, v = 0.5 - 0.1 * z + 0.05 * -0.3;
  double foam = std::min(0.7 * tex->sample(u, v)[0], 1.0);
  auto r = runNode("coastal_foam", {{"depth", Value::scalar(depth)}, {"position", pos(x, z)}, {"normal", n}});
  EXPECT_NEAR(r.scalar("foam"), foam, 1e-12);
  EXPECT_NEAR(r.scalar("specular_scale"), std::pow(1 - foam, 3), 1e-12);
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> d(-1, 3), xz(-1e3, 1e3);
  for (int i = 0; i < 1000; ++i) {
    auto q = runNode("coastal_foam", {{"depth", Value::scalar(d(rng))}, {"position", pos(xz(rng), xz(rng))},
                                       {"crest", Value::scalar(d(rng))}});
    for (const char* o : {"foam", "specular_scale"}) {
      ASSERT_GE(q.scalar(o), 0.0);
      ASSERT_LE(q.scalar(o), 1.0);
    }
  }
}

TEST(ShoreWaves, SeedFormulaByHand) {
  auto env0 = atTime(0);
  // depth 0: sin(0) = 0, ((0 + 1) / 2)^2 = 0.25, fade 1.
  EXPECT_NEAR(runNode("shore_waves", {{"depth", Value::scalar(0)}}, {}, env0).first(), 0.25, 1e-15);
  // depth pi/12 at frequency 6: sin(pi/2) = 1, w = 1, fade 1 - (pi/12)/2.
  EXPECT_NEAR(runNode("shore_waves", {{"depth", Value::scalar(M_PI / 12)}}, {}, env0).first(), 1 - M_PI / 24, 1e-12);
  // Beyond the distance nothing.
  EXPECT_EQ(runNode("shore_waves", {{"depth", Value::scalar(2.5)}}, {}, env0).first(), 0.0);
  // At t = 1e6 s with speed 2: phase written out with std::fmod.
  double t = 1e6, depth = 0.7;
  double w = std::sin(depth * 6 + std::fmod(2 * t, 2 * M_PI)) * 0.5 + 0.5;
  auto r = runNode("shore_waves", {{"depth", Value::scalar(depth)}}, {}, atTime(t));
  EXPECT_NEAR(r.first(), w * w * (1 - depth / 2), 1e-9);
  // Bands move: half a period later a crest has become a trough.
  auto a = runNode("shore_waves", {{"depth", Value::scalar(M_PI / 12)}}, {}, atTime(t));
  auto b = runNode("shore_waves", {{"depth", Value::scalar(M_PI / 12)}}, {}, atTime(t + M_PI / 2));
  EXPECT_GT(std::fabs(a.first() - b.first()), 0.1);
}

// A positive speed runs the bands towards the waterline: the crest at depth pi/12 (t = 0)
// lies 0.5 rad of phase shallower 0.25 s later (speed 2 rad/s, frequency 6 rad/m), and the
// depth it left has fallen from the crest.
TEST(ShoreWaves, APositiveSpeedRunsTowardsTheShore) {
  auto at = [](double depth, double t) { return runNode("shore_waves", {{"depth", Value::scalar(depth)}}, {}, atTime(t)).first(); };
  const double crest0 = M_PI / 12, crest1 = (M_PI / 2 - 0.5) / 6, fade = 0.5;  // fade: 1 - depth / 2 m
  EXPECT_NEAR(at(crest0, 0), 1 - crest0 * fade, 1e-12);
  EXPECT_NEAR(at(crest1, 0.25), 1 - crest1 * fade, 1e-12) << "the crest moved to a smaller depth";
  EXPECT_LT(crest1, crest0);
  EXPECT_LT(at(crest0, 0.25), (1 - crest0 * fade) * 0.9) << "and left the deeper place";
}

const char* kFoamGraph = R"({
  "version": 1, "name": "foam_all",
  "nodes": [
    {"id": "e", "type": "edge_foam", "inputs": {"depth": 0.3, "softness": 0.1}, "options": {"mask": "linear"}},
    {"id": "c", "type": "crest_foam", "inputs": {"height": 0.8}},
    {"id": "k", "type": "coastal_foam", "inputs": {"depth": 0.2, "crest": "c.foam"}, "options": {"dimming": "linear"}},
    {"id": "s", "type": "shore_waves", "inputs": {"depth": 0.4}},
    {"id": "a", "type": "add", "inputs": {"a": "e.foam", "b": "k.foam"}},
    {"id": "b", "type": "mul", "inputs": {"a": "a.out", "b": "k.specular_scale"}},
    {"id": "d", "type": "add", "inputs": {"a": "b.out", "b": "s.waves"}}
  ],
  "outputs": {"fragment": {"color": "d.out"}}
})";

TEST(FoamNodes, CompileTogetherForEveryTarget) {
  std::string messages;
  EXPECT_TRUE(test::compileInline(kFoamGraph, &messages)) << messages;
}

}  // namespace
}  // namespace wg
