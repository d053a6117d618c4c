// fresnel: the exact dielectric values for n = 1.333 that issue 3 quotes, total internal
// reflection from below, Schlick's error against the exact curve, and the power forms.
#include <cmath>

#include <gtest/gtest.h>

#include "codegen/cpu_backend.h"
#include "codegen/compile.h"
#include "core/graph_io.h"
#include "nodes/fresnel_reference.h"
#include "nodes/registry.h"

namespace wg {
namespace {

double rad(double degrees) { return degrees * M_PI / 180.0; }

// The node's eval for a view at `degrees` from the normal.
double fresnelAt(double degrees, const nlohmann::json& options) {
  const NodeSpec* spec = defaultRegistry().find("fresnel");
  return evaluateNode(*spec, options,
                      {{"normal", Value::vector({0, 1, 0})},
                       {"view", Value::vector({std::sin(rad(degrees)), std::cos(rad(degrees)), 0})}},
                      EvalEnvironment{})[0][0];
}

TEST(Fresnel, ExactValuesFromAir) {
  nlohmann::json exact{{"model", "exact"}};
  EXPECT_NEAR(fresnelAt(0, exact), 0.020373, 5e-7);
  EXPECT_NEAR(fresnelAt(30, exact), 0.021436, 5e-7);
  EXPECT_NEAR(fresnelAt(60, exact), 0.059691, 5e-7);
  EXPECT_NEAR(fresnelAt(80, exact), 0.347917, 5e-7);
  EXPECT_NEAR(fresnelAt(90, exact), 1.0, 1e-12);  // cos(90°) is 6e-17 in double
}

TEST(Fresnel, TotalInternalReflectionFromBelow) {
  nlohmann::json below{{"model", "exact"}, {"direction", "water_to_air"}};
  EXPECT_NEAR(fresnelAt(48, below), 0.433077, 5e-7);
  double critical = std::asin(1.0 / 1.333) * 180.0 / M_PI;
  EXPECT_NEAR(critical, 48.6066, 5e-5);
  EXPECT_DOUBLE_EQ(fresnelAt(critical + 1e-6, below), 1.0);
  EXPECT_DOUBLE_EQ(fresnelAt(60, below), 1.0);
  EXPECT_DOUBLE_EQ(fresnelAt(89.9, below), 1.0);
  // Schlick from below uses the transmitted cosine and is total past the critical angle too.
  nlohmann::json schlickBelow{{"model", "schlick"}, {"direction", "water_to_air"}};
  EXPECT_DOUBLE_EQ(fresnelAt(60, schlickBelow), 1.0);
  EXPECT_LT(fresnelAt(30, schlickBelow), 0.1);
}

TEST(Fresnel, SchlickStaysWithinSixHundredthsOfExact) {
  // From air with F0 = ((1 - n) / (1 + n))^2, and from below with the transmitted cosine.
  double n = 1.333, f0 = std::pow((1 - n) / (1 + n), 2);
  double worstAbove = 0, worstBelow = 0;
  for (int i = 0; i <= 9000; ++i) {
    double c = std::cos(rad(i / 100.0));
    worstAbove = std::max(worstAbove, std::fabs(nodes::fresnelSchlick(c, f0) - nodes::fresnelExact(c, 1.0, n)));
    nodes::FresnelSetup below{nodes::FresnelModel::Schlick, true, n, false};
    worstBelow = std::max(worstBelow, std::fabs(nodes::fresnelReference(below, c, f0, 2) - nodes::fresnelExact(c, n, 1.0)));
  }
  EXPECT_LE(worstAbove, 0.06);
  EXPECT_LE(worstBelow, 0.06);
}

TEST(Fresnel, PowerForms) {
  double c = std::cos(rad(60));  // 0.5
  // The classic WebGL water renderer's form, then the stylized water shader's.
  EXPECT_NEAR(fresnelAt(60, {{"model", "power"}}), 1 - 0.25, 1e-12);
  EXPECT_NEAR(fresnelAt(60, {{"model", "power"}, {"power_form", "one_minus_cos"}}), std::pow(1 - c, 2), 1e-12);
}

TEST(Fresnel, DirectionOptionCompilesForEveryTarget) {
  for (const char* model : {"schlick", "exact", "power"})
    for (const char* direction : {"air_to_water", "water_to_air"}) {
      std::string g = std::string(R"({"version": 1, "name": "f", "nodes": [{"id": "f", "type": "fresnel", "options": {"model": ")") +
                      model + R"(", "direction": ")" + direction +
                      R"("}}], "outputs": {"fragment": {"color": "f.reflectance"}}})";
      Diagnostics diags;
      auto graph = parseGraph(g, "f.json", diags);
      ASSERT_TRUE(graph);
      EXPECT_TRUE(compileGraph(*graph, defaultRegistry(), CompileOptions{}, diags)) << model << " " << direction;
    }
}

}  // namespace
}  // namespace wg
