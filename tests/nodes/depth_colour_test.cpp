// The depth-and-colour nodes of the shading set: linearize_depth, water_depth, absorption,
// haze, color_variation. Known values (seed formulas, Pope & Fry's 10 m figures), the sky
// and infinite far plane, negative thickness, and the colour noise's properties.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "nodes/eval_math.h"
#include "nodes/shading_reference.h"
#include "node_eval.h"

namespace wg {
namespace {

using test::runNode;

// The advanced shaders tutorial's linearizeDepth, verbatim.
double seedLinearize(double depth, double n, double f) {
  double z = depth * 2.0 - 1.0;
  return (2.0 * n * f) / (f + n - z * (f - n));
}

TEST(LinearizeDepth, MatchesSeedFormula) {
  for (double nf : {0.0, 1.0})
    for (double d : {0.0, 0.1, 0.5, 0.9, 0.99, 0.999, 1.0}) {
      double n = nf == 0 ? 0.1 : 0.5, f = nf == 0 ? 50 : 1000;
      SCOPED_TRACE(std::to_string(n) + " " + std::to_string(d));
      double got = runNode("linearize_depth", {{"depth", Value::scalar(d)}, {"near_far", Value::vector({n, f})}}).scalar("linear");
      EXPECT_NEAR(got, seedLinearize(d, n, f), 1e-12 * seedLinearize(d, n, f));
    }
  // The ends: the near plane at d = 0 and the far plane at d = 1.
  EXPECT_NEAR(nodes::linearizeDepthReference(0.0, 0.1, 100), 0.1, 1e-15);
  EXPECT_NEAR(nodes::linearizeDepthReference(1.0, 0.1, 100), 100.0, 1e-12);
}

TEST(LinearizeDepth, SkyAndInfiniteFarPlaneStayFinite) {
  const double inf = std::numeric_limits<double>::infinity();
  // far = inf: the infinite-far-plane limit n / (1 - d).
  EXPECT_NEAR(nodes::linearizeDepthReference(0.5, 0.1, inf), 0.2, 1e-15);
  EXPECT_NEAR(nodes::linearizeDepthReference(0.999, 0.1, inf), 100.0, 1e-9);
  // The sky (d = 1) with far = inf or 1e38: a large but finite 1e30.
  for (double f : {inf, 1e38, 3.4e38}) {
    double v = runNode("linearize_depth", {{"depth", Value::scalar(1.0)}, {"near_far", Value::vector({0.1, f})}}).scalar("linear");
    EXPECT_TRUE(std::isfinite(v));
    EXPECT_EQ(v, nodes::kMaxLinearDepth);
  }
  // near -> 0 is floored at 1e-6: finite, and not NaN at d = 1 with far = inf.
  for (double d : {0.0, 0.5, 1.0}) {
    double v = nodes::linearizeDepthReference(d, 0.0, inf);
    EXPECT_TRUE(std::isfinite(v));
    EXPECT_GE(v, 0.0);
  }
  EXPECT_NEAR(nodes::linearizeDepthReference(0.0, 0.0, 100), 1e-6, 1e-18);
}

using test::depthOf;

EvalEnvironment sceneAt(double sceneLinear, double surfaceLinear) {
  EvalEnvironment env;
  env.cameraNearFar = Value::vector({0.1, 100});
  env.sceneDepth = Value::scalar(depthOf(sceneLinear, 0.1, 100));
  env.fragDepth = Value::scalar(depthOf(surfaceLinear, 0.1, 100));
  return env;
}

Value identityView() {
  Value m = Value::ofType(Type::Mat4);
  for (int i = 0; i < 4; ++i) m[i * 4 + i] = 1;
  return m;
}

TEST(WaterDepth, ThicknessAlongTheRayAndVertically) {
  EvalEnvironment env = sceneAt(20, 5);
  // Degenerate (zero) view matrix: the linear-depth difference itself.
  auto a = runNode("water_depth", {}, nlohmann::json::object(), env);
  EXPECT_NEAR(a.scalar("scene_distance"), 20, 1e-9);
  EXPECT_NEAR(a.scalar("surface_distance"), 5, 1e-9);
  EXPECT_NEAR(a.scalar("thickness"), 15, 1e-9);
  // Camera looking down -z (identity view), the ray along the axis: 15.
  env.view = identityView();
  EXPECT_NEAR(runNode("water_depth", {{"view", Value::vector({0, 0, 1})}}, nlohmann::json::object(), env).scalar("thickness"),
              15, 1e-9);
  // The ray 36.87 degrees off the axis (V = (0, 0.6, 0.8)): 15 / 0.8 along the ray,
  // and times V.y = 0.6 vertically.
  Value v = Value::vector({0, 0.6, 0.8});
  EXPECT_NEAR(runNode("water_depth", {{"view", v}}, nlohmann::json::object(), env).scalar("thickness"), 18.75, 1e-9);
  EXPECT_NEAR(runNode("water_depth", {{"view", v}}, {{"measure", "vertical"}}, env).scalar("thickness"), 11.25, 1e-9);
}

TEST(WaterDepth, NegativeThicknessClampsToZero) {
  // The scene (depth 0.3) in front of the water surface (depth 0.5).
  EvalEnvironment env;
  env.sceneDepth = Value::scalar(0.3);
  env.fragDepth = Value::scalar(0.5);
  for (const char* m : {"view_ray", "vertical"}) {
    auto r = runNode("water_depth", {}, {{"measure", m}}, env);
    EXPECT_EQ(r.scalar("thickness"), 0.0) << m;
    EXPECT_LT(r.scalar("scene_distance"), r.scalar("surface_distance"));
  }
  EXPECT_EQ(runNode("water_depth", {}, nlohmann::json::object(), sceneAt(3, 8)).scalar("thickness"), 0.0);
}

TEST(WaterDepth, SkyGivesALargeFiniteThickness) {
  EvalEnvironment env;
  env.sceneDepth = Value::scalar(1.0);
  for (double f : {100.0, 1e38, std::numeric_limits<double>::infinity()}) {
    env.cameraNearFar = Value::vector({0.1, f});
    env.view = identityView();
    double t = runNode("water_depth", {{"view", Value::vector({0, 0.05, 1})}}, nlohmann::json::object(), env).scalar("thickness");
    EXPECT_TRUE(std::isfinite(t)) << f;
    EXPECT_GT(t, 50.0) << f;
    EXPECT_LE(t, 1e30) << f;
  }
}

TEST(Absorption, PopeAndFryAfterTenMetres) {
  auto r = runNode("absorption", {{"distance", Value::scalar(10)}});
  EXPECT_NEAR(r["transmittance"][0], 0.0334, 5e-5);
  EXPECT_NEAR(r["transmittance"][1], 0.5684, 5e-5);
  EXPECT_NEAR(r["transmittance"][2], 0.9119, 5e-5);
  // Exactly exp(-sigma d).
  EXPECT_NEAR(r["transmittance"][0], std::exp(-3.40), 1e-15);
  EXPECT_NEAR(r["transmittance"][1], std::exp(-0.565), 1e-15);
  EXPECT_NEAR(r["transmittance"][2], std::exp(-0.0922), 1e-15);
  // The attenuated colour and the absorbed part.
  auto c = runNode("absorption", {{"distance", Value::scalar(10)}, {"color", Value::vector({0.5, 1, 2})}});
  EXPECT_NEAR(c["color"][0], 0.5 * std::exp(-3.40), 1e-15);
  EXPECT_NEAR(c["color"][2], 2 * std::exp(-0.0922), 1e-15);
  EXPECT_NEAR(c["absorbed"][1], 1 - std::exp(-0.565), 1e-15);
  // Beer-Lambert composes: T(a + b) = T(a) T(b).
  auto t3 = runNode("absorption", {{"distance", Value::scalar(3)}})["transmittance"];
  auto t7 = runNode("absorption", {{"distance", Value::scalar(7)}})["transmittance"];
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(t3[i] * t7[i], r["transmittance"][i], 1e-15);
}

TEST(Absorption, SeedOneRelativeModel) {
  nlohmann::json rel{{"model", "relative"}};
  // The deferred water article's listing 12, written out: blue linear over the max distance, red and green
  // scaled further, each clamped, all squared.
  auto seed = [](double d, double m, double kr, double kg) {
    double b = std::min(1.0, std::max(0.0, (m - d) * (1.0 / m)));
    double g = std::min(1.0, std::max(0.0, b * (1 - d * kg)));
    double r = std::min(1.0, std::max(0.0, b * (1 - d * kr)));
    return Value::vector({r * r, g * g, b * b});
  };
  for (double d : {0.0, 1.0, 5.0, 8.0, 20.0, 100.0, 300.0}) {
    SCOPED_TRACE(d);
    Value t = runNode("absorption", {{"distance", Value::scalar(d)}}, rel)["transmittance"];
    Value e = seed(d, 220, 0.1125, 0.0223);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(t[i], e[i], 1e-12);
  }
  // The defaults are fitted to Pope & Fry at 5 m.
  Value t5 = runNode("absorption", {{"distance", Value::scalar(5)}}, rel)["transmittance"];
  Value b5 = runNode("absorption", {{"distance", Value::scalar(5)}})["transmittance"];
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(t5[i], b5[i], 2e-3);
  // Custom coefficients.
  Value c = runNode("absorption", {{"distance", Value::scalar(2)}, {"max_distance", Value::scalar(10)},
                                   {"relative_red", Value::scalar(0.25)}, {"relative_green", Value::scalar(0.1)}},
                    rel)["transmittance"];
  Value e = seed(2, 10, 0.25, 0.1);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(c[i], e[i], 1e-12);
}

TEST(Haze, SeedOneBlend) {
  Value red = Value::vector({1, 0, 0}), blue = Value::vector({0, 0, 1});
  for (double d : {0.0, 500.0, 1000.0, 1999.0, 2000.0, 5000.0}) {
    SCOPED_TRACE(d);
    auto r = runNode("haze", {{"color", red}, {"background", blue}, {"distance", Value::scalar(d)}});
    double seedHaze = 1.0 - std::max(0.0, (2000.0 - d) * 0.0005);
    EXPECT_NEAR(r.scalar("factor"), seedHaze, 1e-12);
    EXPECT_NEAR(r["color"][0], 1 - seedHaze, 1e-12);
    EXPECT_NEAR(r["color"][2], seedHaze, 1e-12);
  }
  EXPECT_NEAR(runNode("haze", {{"color", red}, {"distance", Value::scalar(50)}, {"haze_distance", Value::scalar(100)}})
                  .scalar("factor"),
              0.5, 1e-12);
}

TEST(ColorVariation, NoiseProperties) {
  // In [0, 1), equal to the lattice values at integer points, continuous, periodic over 256.
  for (int x = -3; x <= 3; ++x)
    for (int y = -3; y <= 3; ++y) {
      double n = nodes::colorVariationNoise(x, y);
      EXPECT_EQ(n, nodes::colorVariationCell(x, y));
      EXPECT_GE(n, 0.0);
      EXPECT_LT(n, 1.0);
      EXPECT_NEAR(nodes::colorVariationNoise(x + 0.37, y + 0.81), nodes::colorVariationNoise(x + 256 + 0.37, y - 512 + 0.81),
                  1e-12);
    }
  double prev = nodes::colorVariationNoise(0.0, 0.5), maxStep = 0, lo = 1, hi = 0;
  for (int i = 1; i <= 100000; ++i) {
    double n = nodes::colorVariationNoise(i * 1e-3, 0.5 + i * 7e-4);
    maxStep = std::max(maxStep, std::abs(n - prev));
    lo = std::min(lo, n), hi = std::max(hi, n);
    prev = n;
  }
  EXPECT_LT(maxStep, 0.01);  // continuous: the gradient is at most 1.5 per unit
  EXPECT_LT(lo, 0.15);       // and it varies over its range
  EXPECT_GT(hi, 0.85);
  // Distinct cells hash to distinct values (no short period in the hash).
  int same = 0;
  for (int i = 0; i < 255; ++i) same += nodes::colorVariationCell(i, 0) == nodes::colorVariationCell(i + 1, 0);
  EXPECT_LT(same, 3);
}

TEST(ColorVariation, SeedFourTerms) {
  Value base = Value::vector({0.1, 0.3, 0.5});
  nlohmann::json still{{"drift", 0.0}};
  // Only the trough darkening: height 0 darkens by 0.15, height 1 not at all.
  auto t0 = runNode("color_variation", {{"color", base}, {"height", Value::scalar(0)}, {"slope_strength", Value::scalar(0)},
                                        {"noise_strength", Value::scalar(0)}}, still);
  EXPECT_NEAR(t0["color"][1], 0.3 * 0.85, 1e-12);
  auto t1 = runNode("color_variation", {{"color", base}, {"height", Value::scalar(1)}, {"slope_strength", Value::scalar(0)},
                                        {"noise_strength", Value::scalar(0)}}, still);
  EXPECT_NEAR(t1["color"][2], 0.5, 1e-12);
  // Slope: a normal leaning towards the sun (facing = 1 with a horizontal sun and normal)
  // takes the warm shift, leaning away the cool one.
  Value sun = Value::vector({1, 0, 0});
  auto warm = runNode("color_variation", {{"color", base}, {"height", Value::scalar(1)}, {"normal", Value::vector({1, 0, 0})},
                                          {"sun", sun}, {"noise_strength", Value::scalar(0)}}, still);
  EXPECT_NEAR(warm["color"][0], 0.1 + 0.03 * 0.2, 1e-12);
  EXPECT_NEAR(warm["color"][2], 0.5 - 0.02 * 0.2, 1e-12);
  auto cool = runNode("color_variation", {{"color", base}, {"height", Value::scalar(1)}, {"normal", Value::vector({-1, 0, 0})},
                                          {"sun", sun}, {"noise_strength", Value::scalar(0)}}, still);
  EXPECT_NEAR(cool["color"][0], 0.1 - 0.03 * 0.2, 1e-12);
  // Flat water (N = up): facing 0, the midpoint of the two shifts.
  auto flat = runNode("color_variation", {{"color", base}, {"height", Value::scalar(1)}, {"normal", Value::vector({0, 1, 0})},
                                          {"noise_strength", Value::scalar(0)}}, still);
  EXPECT_NEAR(flat["color"][1], 0.3 + 0.02 * 0.2, 1e-12);
  // Noise hue shift: mix((-0.02, 0.02, 0.04), (0.02, 0.04, -0.02), noise) * 0.1.
  Value pos = Value::vector({123.4, 0, -56.7});
  auto nz = runNode("color_variation", {{"color", base}, {"height", Value::scalar(1)}, {"position", pos},
                                        {"slope_strength", Value::scalar(0)}}, still);
  double n = nodes::colorVariationNoise(123.4 * 0.02, -56.7 * 0.02);
  EXPECT_EQ(nz.scalar("noise"), n);
  EXPECT_NEAR(nz["color"][0], 0.1 + 0.1 * glsl::mix(-0.02, 0.02, n), 1e-12);
  EXPECT_NEAR(nz["color"][2], 0.5 + 0.1 * glsl::mix(0.04, -0.02, n), 1e-12);
}

TEST(ColorVariation, DriftIsWrappedExactly) {
  Value pos = Value::vector({10, 0, 20});
  auto at = [&](double t) {
    EvalEnvironment env;
    env.time = Value::scalar(t);
    return runNode("color_variation", {{"color", Value::vector({0, 0, 0})}, {"position", pos}}, nlohmann::json::object(), env)
        .scalar("noise");
  };
  // The source's noise(worldPos * 0.02 + time * 0.05), unwrapped, in double.
  for (double t : {0.0, 3.5, 1000.0, 13107.0, 524288.0, 1e6}) {
    SCOPED_TRACE(t);
    EXPECT_NEAR(at(t), nodes::colorVariationNoise(0.2 + 0.05 * t, 0.4 + 0.05 * t), 1e-6);
  }
  // One full period of the drift (256 / 0.05 s) later the pattern is the same.
  EXPECT_NEAR(at(100.0), at(100.0 + 256 / 0.05), 1e-9);
}

TEST(DepthAndColourNodes, CompileTogetherForEveryTarget) {
  std::string graph = R"({
    "version": 1, "name": "depth_colour_set",
    "nodes": [
      {"id": "depth", "type": "water_depth", "options": {"measure": "vertical"}},
      {"id": "lin", "type": "linearize_depth", "inputs": {"depth": 0.7}},
      {"id": "abs", "type": "absorption", "inputs": {"distance": "depth.thickness", "color": [0.2, 0.5, 0.6]}},
      {"id": "rel", "type": "absorption", "options": {"model": "relative"}, "inputs": {"distance": "lin.linear"}},
      {"id": "var", "type": "color_variation", "inputs": {"color": "abs.color", "height": 0.3}},
      {"id": "sum", "type": "add", "inputs": {"a": "var.color", "b": "rel.transmittance"}},
      {"id": "haze", "type": "haze", "inputs": {"color": "sum.out", "distance": "depth.surface_distance"}}
    ],
    "outputs": {"fragment": {"color": "haze.color", "alpha": 1}}
  })";
  EXPECT_EQ(test::compileGraphText(graph), "");
}

}  // namespace
}  // namespace wg
