// subsurface (the stylized water shader, section 8): the source's HLSL written out in double, the height
// factor, and a graph that feeds it the Gerstner-free inputs compiles for every target.
#include <cmath>

#include <gtest/gtest.h>

#include "nodes/eval_math.h"
#include "node_eval.h"

namespace wg {
namespace {

using test::runNode;

Value unit(double x, double y, double z) { return glsl::safeNormalize(Value::vector({x, y, z})); }

// The stylized water shader: H = normalize(lightDir + worldNormal * _SSSDistortion);
// VdotH = pow(saturate(dot(viewDir, -H)), _SSSPower); waveHeightFactor = saturate(h * 2 + 0.5);
// sss = _SSSColor * VdotH * _SSSStrength * waveHeightFactor.
double seedIntensity(const Value& n, const Value& v, const Value& l, double distortion, double power, double strength,
                     double height) {
  Value h = glsl::safeNormalize(Value::vector({l[0] + n[0] * distortion, l[1] + n[1] * distortion, l[2] + n[2] * distortion}));
  double vdoth = std::pow(glsl::saturate(-glsl::dot(v, h)), power);
  return vdoth * strength * glsl::saturate(height * 2 + 0.5);
}

TEST(Subsurface, SeedThreeFormula) {
  Value n = unit(0.2, 1, -0.1), v = unit(-0.8, 0.3, 0.1), l = unit(1, 0.25, 0);
  for (double distortion : {0.0, 0.3, 0.8})
    for (double power : {1.0, 4.0, 12.0})
      for (double height : {-0.5, -0.1, 0.0, 0.2, 0.4}) {
        SCOPED_TRACE(std::to_string(distortion) + " " + std::to_string(power) + " " + std::to_string(height));
        auto r = runNode("subsurface", {{"normal", n}, {"view", v}, {"light", l}, {"distortion", Value::scalar(distortion)},
                                        {"power", Value::scalar(power)}, {"strength", Value::scalar(1.5)},
                                        {"height", Value::scalar(height)}, {"color", Value::vector({0, 0.5, 1})}});
        double e = seedIntensity(n, v, l, distortion, power, 1.5, height);
        EXPECT_NEAR(r.scalar("intensity"), e, 1e-12);
        EXPECT_NEAR(r["color"][1], 0.5 * e, 1e-12);
        EXPECT_NEAR(r["color"][2], e, 1e-12);
      }
}

TEST(Subsurface, GlowsOnlyAgainstTheLight) {
  Value up = Value::vector({0, 1, 0});
  Value sun = unit(1, 0.2, 0);
  // Looking towards the sun, through the crest: V opposite L horizontally.
  double against = runNode("subsurface", {{"normal", up}, {"view", unit(-1, 0.2, 0)}, {"light", sun},
                                          {"height", Value::scalar(0.25)}}).scalar("intensity");
  double with = runNode("subsurface", {{"normal", up}, {"view", unit(1, 0.2, 0)}, {"light", sun},
                                       {"height", Value::scalar(0.25)}}).scalar("intensity");
  EXPECT_GT(against, 0.3);
  EXPECT_EQ(with, 0.0);
  // Troughs (height <= -0.25) do not glow; crests (height >= 0.25) glow fully.
  EXPECT_EQ(runNode("subsurface", {{"normal", up}, {"view", unit(-1, 0.2, 0)}, {"light", sun},
                                   {"height", Value::scalar(-0.3)}}).scalar("intensity"), 0.0);
  EXPECT_NEAR(runNode("subsurface", {{"normal", up}, {"view", unit(-1, 0.2, 0)}, {"light", sun},
                                     {"height", Value::scalar(7)}}).scalar("intensity"), against, 1e-12);
}

TEST(Subsurface, CompilesInAGraphForEveryTarget) {
  std::string graph = R"({
    "version": 1, "name": "scattering_set",
    "nodes": [
      {"id": "pos", "type": "world_position"},
      {"id": "h", "type": "split", "inputs": {"v": "pos.out"}},
      {"id": "sss", "type": "subsurface", "inputs": {"height": "h.y", "power": 6}},
      {"id": "out", "type": "add", "inputs": {"a": "sss.color", "b": [0.0, 0.1, 0.2]}}
    ],
    "outputs": {"fragment": {"color": "out.out", "alpha": 1}}
  })";
  EXPECT_EQ(test::compileGraphText(graph), "");
}

}  // namespace
}  // namespace wg
