// The caustics nodes: voronoi_caustics (the stylized water shader: (1 - clamp(F1, 0, 1))^3 per layer, the
// F1 > 1 case, layer combinations, huge time) and texture_caustics (the deferred water article: the ninth
// power of 1 - |a + b - 1| from two scrolling texture samples, always in [0, 1]).
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "nodes/foam_caustics_reference.h"
#include "nodes/noise_reference.h"
#include "nodes/texture_source.h"
#include "node_eval.h"

namespace wg {
namespace {

using test::runNode;

const Value kFarPoint = Value::vector({50.09375, 86.09375});  // F1 = 1.2008 there (jitter 1)

TEST(VoronoiCaustics, LayerIntensityByHand) {
  EXPECT_EQ(nodes::voronoiCausticsIntensity(0.0), 1.0);
  EXPECT_EQ(nodes::voronoiCausticsIntensity(0.5), 0.125);
  EXPECT_EQ(nodes::voronoiCausticsIntensity(1.0), 0.0);
  // F1 > 1: clamped, so 0 and not (1 - 1.2)^3 = -0.008 (or NaN from a pow of a negative base).
  EXPECT_EQ(nodes::voronoiCausticsIntensity(1.2), 0.0);
  EXPECT_EQ(nodes::voronoiCausticsIntensity(-0.1), 1.0);
}

TEST(VoronoiCaustics, FirstDistanceAboveOneStaysFiniteAndInRange) {
  double f1 = nodes::noise::voronoi(kFarPoint[0], kFarPoint[1], 1.0, 0.0, false, true).f1;
  ASSERT_GT(f1, 1.0);
  for (const char* search : {"3x3", "2x2"}) {
    SCOPED_TRACE(search);
    auto one = runNode("voronoi_caustics", {{"p", kFarPoint}, {"scale", Value::scalar(1)}},
                        {{"animation", "static"}, {"layers", "1"}, {"search", search}});
    EXPECT_EQ(one.first(), 0.0);
    for (const char* combine : {"average", "min", "multiply"}) {
      auto two = runNode("voronoi_caustics", {{"p", kFarPoint}, {"scale", Value::scalar(1)}},
                          {{"animation", "static"}, {"combine", combine}, {"search", search}});
      EXPECT_TRUE(std::isfinite(two.first()));
      EXPECT_GE(two.first(), 0.0);
      EXPECT_LE(two.first(), 1.0);
    }
  }
}

TEST(VoronoiCaustics, SeedLayersAndCombinations) {
  // The stylized water shader: c1 from q, c2 from 1.3 q + 5 at 1.2 times the speed; averaged.
  Value p = Value::vector({0.37, 0.81});
  double scale = 4, t = 2.5, speed = 0.8;
  double qx = 0.37 * scale, qy = 0.81 * scale;
  double ph1 = std::fmod(speed * t, 2 * M_PI), ph2 = std::fmod(1.2 * speed * t, 2 * M_PI);
  double f1a = nodes::noise::voronoi(qx, qy, 1.0, ph1, true, true).f1;
  double f1b = nodes::noise::voronoi(1.3 * qx + 5, 1.3 * qy + 5, 1.0, ph2, true, true).f1;
  double c1 = std::pow(1 - std::min(f1a, 1.0), 3), c2 = std::pow(1 - std::min(f1b, 1.0), 3);
  nlohmann::json o{{"speed", speed}};
  auto env = test::atTime(t);
  EXPECT_NEAR(runNode("voronoi_caustics", {{"p", p}}, o, env).first(), 0.5 * (c1 + c2), 1e-12);
  o["combine"] = "min";
  EXPECT_NEAR(runNode("voronoi_caustics", {{"p", p}}, o, env).first(), std::min(c1, c2), 1e-12);
  o["combine"] = "multiply";
  EXPECT_NEAR(runNode("voronoi_caustics", {{"p", p}}, o, env).first(), c1 * c2, 1e-12);
  o["layers"] = "1";
  EXPECT_NEAR(runNode("voronoi_caustics", {{"p", p}, {"intensity", Value::scalar(2)}}, o, env).first(), 2 * c1, 1e-12);
}

TEST(VoronoiCaustics, HugeTimeStaysFiniteAndPeriodic) {
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> d(-20, 20);
  for (int i = 0; i < 200; ++i) {
    Value p = Value::vector({d(rng), d(rng)});
    double c = runNode("voronoi_caustics", {{"p", p}}, {}, test::atTime(1e6)).first();
    ASSERT_TRUE(std::isfinite(c));
    ASSERT_GE(c, 0.0);
    ASSERT_LE(c, 1.0);
    // speed 1 and 1.2: both phases return after 10 pi seconds.
    double c2 = runNode("voronoi_caustics", {{"p", p}}, {}, test::atTime(1e6 + 10 * M_PI)).first();
    ASSERT_NEAR(c, c2, 1e-7);
    double ci = runNode("voronoi_caustics", {{"p", p}, {"time", Value::scalar(1e6)}}, {{"animation", "time_input"}}).first();
    ASSERT_NEAR(ci, c, 1e-12);
  }
}

TEST(TextureCaustics, ShapeByHand) {
  EXPECT_EQ(nodes::textureCausticsShape(0.5, 0.5), 1.0);
  EXPECT_EQ(nodes::textureCausticsShape(0.3, 0.7), 1.0);
  EXPECT_NEAR(nodes::textureCausticsShape(0.5, 0.75), std::pow(0.75, 9), 1e-15);
  EXPECT_NEAR(nodes::textureCausticsShape(0.2, 0.3), std::pow(0.5, 9), 1e-15);
  EXPECT_EQ(nodes::textureCausticsShape(0.0, 0.0), 0.0);
  EXPECT_EQ(nodes::textureCausticsShape(1.0, 1.0), 0.0);
  EXPECT_EQ(nodes::textureCausticsShape(5.0, 5.0), 0.0);  // base clamped, not (-8)^9
}

TEST(TextureCaustics, MatchesTheSeedFormulaOnTheBuiltinHeightTexture) {
  auto tex = generateBuiltinTexture("height");
  ASSERT_TRUE(tex);
  Value pos = Value::vector({3.7, 0.2, -8.9});
  double t = 40.0, vx = 0.02, vy = 0.01, k = 0.1;
  double u = k * 3.7 + 0.5, v = 0.5 + k * 8.9;
  double mu = t * vx - std::floor(t * vx), mv = t * vy - std::floor(t * vy);
  double a = tex->sample(u + mu, v + mv)[0], b = tex->sample(1.5 * u - mu, 1.5 * v - mv)[0];
  double c = std::pow(std::min(std::max(1 - std::fabs(a + b - 1), 0.0), 1.0), 9);
  auto r = runNode("texture_caustics", {{"position", pos}, {"time", Value::scalar(t)}, {"intensity", Value::scalar(0.8)}});
  EXPECT_NEAR(r.first(), 0.8 * c, 1e-12);
}

TEST(TextureCaustics, AlwaysInUnitRangeIncludingHugeTime) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> d(-1e4, 1e4), tt(0, 1e6);
  double hi = 0;
  for (int i = 0; i < 2000; ++i) {
    double t = i % 10 == 0 ? 1e6 : tt(rng);
    auto r = runNode("texture_caustics", {{"position", Value::vector({d(rng), 0, d(rng)})}, {"time", Value::scalar(t)}});
    ASSERT_TRUE(std::isfinite(r.first()));
    ASSERT_GE(r.first(), 0.0);
    ASSERT_LE(r.first(), 1.0);
    hi = std::max(hi, r.first());
  }
  EXPECT_GT(hi, 0.5);  // the pattern really has bright spots
}

const char* kCausticsGraph = R"({
  "version": 1, "name": "caustics_all",
  "nodes": [
    {"id": "wp", "type": "world_position"},
    {"id": "xz", "type": "swizzle", "inputs": {"x": "wp.out"}, "options": {"mask": "xz"}},
    {"id": "v", "type": "voronoi_caustics", "inputs": {"p": "xz.out"}},
    {"id": "v1", "type": "voronoi_caustics", "inputs": {"p": "xz.out", "time": 2},
     "options": {"layers": "1", "search": "2x2", "animation": "time_input", "combine": "min"}},
    {"id": "t", "type": "texture_caustics", "inputs": {"velocity": [0.1, -0.05]}},
    {"id": "a", "type": "add", "inputs": {"a": "v.caustics", "b": "t.caustics"}},
    {"id": "b", "type": "add", "inputs": {"a": "a.out", "b": "v1.caustics"}}
  ],
  "outputs": {"fragment": {"color": "b.out"}}
})";

TEST(CausticsNodes, CompileTogetherForEveryTarget) {
  std::string messages;
  auto result = test::compileInline(kCausticsGraph, &messages);
  ASSERT_TRUE(result) << messages;
  // Two layers at speeds 1 and 1.2: two time-phase uniforms, shared with nothing else.
  for (const auto& f : result->files)
    if (f.name.find("glsl330.frag") != std::string::npos) {
      EXPECT_NE(f.contents.find("u_phase0"), std::string::npos);
      EXPECT_NE(f.contents.find("u_phase1"), std::string::npos);
      EXPECT_NE(f.contents.find("wg_texture_caustics_shape"), std::string::npos);
    }
}

}  // namespace
}  // namespace wg
