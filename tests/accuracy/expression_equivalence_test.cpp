// Water techniques written as `expression` formulas over the math vocabulary against the
// built-in nodes that implement them: Schlick Fresnel, Beer-Lambert absorption and the
// linear depth tint. In double the formula and the node agree within 1e-12 over a spread
// of inputs that crosses every clamp; on the GL runtime (both targets) the formula's
// float32 result stays within the built-in node's own error bound of the node's double
// reference, so writing a technique by hand costs no accuracy.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "accuracy/node_probe.h"
#include "accuracy/probe_cases.h"
#include "codegen/cpu_backend.h"
#include "core/diagnostic_text.h"
#include "nodes/registry.h"
#include "runtime/egl_context.h"
#include "test_support.h"

namespace wg::accuracy {
namespace {

using FormulaCaseInputs = std::vector<std::pair<std::string, Value>>;

// One technique: the built-in node's output, and the formula standing for it. The
// formula's inputs carry the node's port names, so one input set feeds both.
struct Technique {
  std::string name;
  std::string node;
  nlohmann::json nodeOptions;
  std::string output;
  nlohmann::json expression;  // the expression node's options
  std::vector<FormulaCaseInputs> cases;
};

Value vec3Of(double x, double y, double z) { return Value::vector({x, y, z}); }
Value scalarOf(double x) { return Value::scalar(x); }

Value unitVector(double x, double y, double z) {
  double n = std::sqrt(x * x + y * y + z * z);
  return vec3Of(x / n, y / n, z / n);
}

const std::vector<Technique>& techniques() {
  static const std::vector<Technique> all = [] {
    std::vector<Technique> t;
    // Schlick: F0 + (1 - F0)(1 - c)^5 with c = clamp(N.V, 0, 1); views from straight down
    // to grazing, and one from behind the surface (c clamps to 0).
    Technique schlick{"schlick_fresnel", "fresnel", {{"model", "schlick"}}, "reflectance",
                      {{"inputs", {{"normal", "vec3"}, {"view", "vec3"}, {"f0", "float"}}},
                       {"formula", "f0 + (1.0 - f0) * pow(1.0 - clamp(dot(normal, view), 0.0, 1.0), 5.0)"}},
                      {}};
    for (double angle : {0.0, 20.0, 45.0, 60.0, 75.0, 85.0, 89.0, 89.9, 95.0}) {
      double a = angle * std::acos(-1.0) / 180;
      for (double f0 : {0.02, 0.2})
        schlick.cases.push_back({{"normal", vec3Of(0, 1, 0)}, {"view", unitVector(std::sin(a), std::cos(a), 0)}, {"f0", scalarOf(f0)}});
    }
    t.push_back(schlick);
    // Beer-Lambert: color * exp(-max(sigma, 0) * clamp(d, 0, 1e30)); negative and huge
    // distances, a negative coefficient.
    Technique beer{"beer_lambert", "absorption", {{"model", "beer_lambert"}}, "color",
                   {{"inputs", {{"color", "vec3"}, {"sigma", "vec3"}, {"distance", "float"}}},
                    {"formula", "color * exp(-max(sigma, 0.0) * clamp(distance, 0.0, 1e30))"}},
                   {}};
    for (double d : {-2.0, 0.0, 0.5, 3.0, 10.0, 40.0, 1e30})
      beer.cases.push_back({{"color", vec3Of(0.9, 0.8, 0.7)}, {"sigma", vec3Of(0.34, 0.0565, 0.00922)}, {"distance", scalarOf(d)}});
    beer.cases.push_back({{"color", vec3Of(1, 1, 1)}, {"sigma", vec3Of(-0.5, 0.2, 0)}, {"distance", scalarOf(4)}});
    t.push_back(beer);
    // Linear depth tint: mix(shallow, deep, saturate(depth / max(max_depth, 1e-6))).
    Technique tint{"depth_tint", "depth_tint", {{"curve", "linear"}}, "color",
                   {{"inputs", {{"depth", "float"}, {"shallow", "vec3"}, {"deep", "vec3"}, {"max_depth", "float"}}},
                    {"formula", "mix(shallow, deep, clamp(depth / max(max_depth, 1e-6), 0.0, 1.0))"}},
                   {}};
    for (double depth : {-1.0, 0.0, 2.5, 7.0, 10.0, 25.0, 1e30})
      tint.cases.push_back({{"depth", scalarOf(depth)}, {"shallow", vec3Of(0, 0.8, 0.7)}, {"deep", vec3Of(0, 0.1, 0.3)}, {"max_depth", scalarOf(10)}});
    tint.cases.push_back({{"depth", scalarOf(3)}, {"shallow", vec3Of(0, 0.8, 0.7)}, {"deep", vec3Of(0, 0.1, 0.3)}, {"max_depth", scalarOf(0)}});
    t.push_back(tint);
    return t;
  }();
  return all;
}

TEST(ExpressionEquivalence, FormulasAgreeWithTheBuiltInNodesInDouble) {
  const NodeSpec* expression = defaultRegistry().find("expression");
  ASSERT_NE(expression, nullptr);
  int compared = 0;
  for (const auto& t : techniques()) {
    const NodeSpec* node = defaultRegistry().find(t.node);
    ASSERT_NE(node, nullptr) << t.node;
    for (const auto& inputs : t.cases) {
      Value want = evaluateNode(*node, t.nodeOptions, inputs, EvalEnvironment{})[static_cast<size_t>(node->outputIndex(t.output))];
      Value got = evaluateNode(*expression, t.expression, inputs, EvalEnvironment{})[0];
      ASSERT_EQ(got.type, want.type) << t.name;
      for (int c = 0; c < want.size(); ++c) {
        EXPECT_TRUE(std::isfinite(got[c])) << t.name;
        EXPECT_NEAR(got[c], want[c], 1e-12) << t.name << " component " << c << " inputs " << inputs.back().second[0];
      }
      ++compared;
    }
  }
  EXPECT_EQ(compared, 18 + 8 + 8);
}

std::vector<ProbeCase> probeCases(const Technique& t) {
  std::vector<ProbeCase> cases;
  for (const auto& inputs : t.cases) {
    ProbeCase c;
    c.name = t.name + " case " + std::to_string(cases.size());
    c.env = defaultProbeEnvironment();
    for (const auto& [port, v] : inputs) c.inputs.emplace_back(port, toFloat32(v));
    cases.push_back(std::move(c));
  }
  return cases;
}


class ExpressionEquivalenceOnGpu : public ::testing::TestWithParam<Target> {};

// The formula's GPU result against the built-in node's double reference, within the
// bound the probe holds the built-in node to for the same case.
TEST_P(ExpressionEquivalenceOnGpu, FormulasStayWithinTheBuiltInNodesErrorBound) {
  auto context = rt::EglContext::create(GetParam() == Target::Es300 ? rt::GlApi::Es32 : rt::GlApi::DesktopGl45);
  const NodeSpec* expression = defaultRegistry().find("expression");
  for (const auto& t : techniques()) {
    const NodeSpec* node = defaultRegistry().find(t.node);
    std::vector<ProbeCase> cases = probeCases(t);
    Diagnostics diags;
    auto builtIn = probeNode(*node, t.nodeOptions, t.output, cases, GetParam(), diags);
    ASSERT_TRUE(builtIn) << t.name << ": " << core_test::dump(diags);
    auto formula = probeNode(*expression, t.expression, "out", cases, GetParam(), diags);
    ASSERT_TRUE(formula) << t.name << ": " << core_test::dump(diags);
    ASSERT_EQ(builtIn->cases.size(), cases.size());
    ASSERT_EQ(formula->cases.size(), cases.size());
    EXPECT_TRUE(builtIn->passed()) << formatProbeText(*builtIn);
    EXPECT_TRUE(formula->passed()) << formatProbeText(*formula);
    for (size_t i = 0; i < cases.size(); ++i) {
      const ProbeCaseResult& ref = builtIn->cases[i];
      const ProbeCaseResult& got = formula->cases[i];
      ASSERT_EQ(got.components, ref.components) << t.name;
      for (int c = 0; c < ref.components; ++c) {
        double r = ref.reference[static_cast<size_t>(c)];
        double bound = node->tolerance * std::max(1.0, std::abs(r)) + ref.conditioning;
        EXPECT_TRUE(std::isfinite(got.gpu[static_cast<size_t>(c)])) << got.name;
        EXPECT_LE(std::abs(got.gpu[static_cast<size_t>(c)] - r), bound)
            << got.name << " component " << c << ": formula on the GPU " << got.gpu[static_cast<size_t>(c)]
            << ", node's double reference " << r;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Targets, ExpressionEquivalenceOnGpu, ::testing::Values(Target::Glsl330, Target::Es300),
                         [](const auto& info) { return std::string(targetName(info.param)); });

}  // namespace
}  // namespace wg::accuracy
