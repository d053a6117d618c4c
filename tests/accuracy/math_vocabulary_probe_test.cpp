// The math vocabulary on the GL runtime, both targets: each new node probed alone on vec3
// inputs of ordinary size (its hard cases run in the hard-case suite), GPU float32
// against the double reference within the node's documented error bound. vec3 inputs
// reach the per-type library variants and the component-wise built-ins; each case's
// inputs are uniforms, so nothing folds.
#include <gtest/gtest.h>

#include "accuracy/node_probe.h"
#include "accuracy/probe_cases.h"
#include "nodes/registry.h"
#include "runtime/egl_context.h"
#include "test_support.h"

namespace wg::accuracy {
namespace {

using Inputs = std::vector<std::pair<std::string, Value>>;

struct NodeRun {
  std::string node;
  nlohmann::json options;
  std::vector<Inputs> cases;
};

Value v3(double x, double y, double z) { return Value::vector({x, y, z}); }
Inputs x3(double a, double b, double c) { return {{"x", v3(a, b, c)}}; }

const std::vector<NodeRun>& runs() {
  static const Value up = v3(0, 1, 0);
  static const std::vector<NodeRun> r = [] {
    std::vector<NodeRun> out;
    auto object = nlohmann::json::object();
    Inputs spread = x3(-3.7, 0.25, 12.5), halves = x3(-0.5, 1.5, 2.5);
    for (const char* n : {"fract", "floor", "ceil", "round", "trunc", "sign", "negate", "one_minus", "sinh", "cosh", "atan"})
      out.push_back({n, object, {spread, halves}});
    out.push_back({"mod", object, {{{"x", v3(-3.7, 0.25, 12.5)}, {"y", v3(1, 0.3, -4)}}}});
    out.push_back({"step", object, {{{"edge", v3(0, 0.5, 1)}, {"x", v3(-3.7, 0.5, 12.5)}}}});
    for (const char* n : {"exp", "exp2"}) out.push_back({n, object, {spread, x3(-80, 40, 87)}});
    for (const char* n : {"log", "log2", "sqrt", "inversesqrt"}) out.push_back({n, object, {x3(0.001, 0.25, 12.5), x3(1e-20, 1, 1e20)}});
    out.push_back({"tan", object, {x3(-1.2, 0.25, 3.0)}});
    for (const char* n : {"asin", "acos"}) out.push_back({n, object, {x3(-0.99, 0.25, 0.75)}});
    out.push_back({"tanh", object, {x3(-3.7, 0.25, 1.5)}});
    out.push_back({"atan2", object, {{{"y", v3(-1, 0.25, 3)}, {"x", v3(-2, 0.5, -0.1)}}}});
    out.push_back({"distance", object, {{{"a", v3(1, 2, 3)}, {"b", v3(-2, 6, 3.5)}}}});
    out.push_back({"reflect", object, {{{"incident", v3(0.6, -0.8, 0)}, {"normal", up}}}});
    out.push_back({"refract", object,
                   {{{"incident", v3(0.6, -0.8, 0)}, {"normal", up}, {"eta", Value::scalar(0.75)}},
                    {{"incident", v3(0.8, -0.6, 0)}, {"normal", up}, {"eta", Value::scalar(1.333)}}}});
    out.push_back({"faceforward", object,
                   {{{"normal", up}, {"incident", v3(0.6, -0.8, 0)}, {"reference", up}},
                    {{"normal", up}, {"incident", v3(0.6, 0.8, 0)}, {"reference", up}}}});
    Inputs compared = {{"a", v3(-1, 0.5, 2)}, {"b", v3(0.5, 0.5, 0.5)}};
    for (const char* op : {"less", "equal"}) {
      out.push_back({"compare", {{"op", op}}, {compared}});
      Inputs chosen = compared;
      chosen.push_back({"if_true", v3(1, 2, 3)});
      chosen.push_back({"if_false", v3(-1, -2, -3)});
      out.push_back({"select", {{"op", op}}, {chosen}});
    }
    out.push_back({"inverse_mix", object, {{{"a", v3(0, 1, -2)}, {"b", v3(1, 3, 2)}, {"x", v3(0.25, 2, 5)}}}});
    return out;
  }();
  return r;
}

class MathVocabularyOnGpu : public ::testing::TestWithParam<Target> {};

TEST_P(MathVocabularyOnGpu, EveryNodeWithinItsErrorBound) {
  auto context = rt::EglContext::create(GetParam() == Target::Es300 ? rt::GlApi::Es32 : rt::GlApi::DesktopGl45);
  int probed = 0;
  for (const auto& run : runs()) {
    const NodeSpec* spec = defaultRegistry().find(run.node);
    ASSERT_NE(spec, nullptr) << run.node;
    std::vector<ProbeCase> cases;
    for (const auto& inputs : run.cases) {
      ProbeCase c;
      c.name = run.node + " case " + std::to_string(cases.size());
      c.env = defaultProbeEnvironment();
      for (const auto& [port, v] : inputs) c.inputs.emplace_back(port, toFloat32(v));
      cases.push_back(std::move(c));
    }
    Diagnostics diags;
    auto report = probeNode(*spec, run.options, "", cases, GetParam(), diags);
    std::string why;
    for (const auto& d : diags.all()) why += formatText(d) + "\n";
    ASSERT_TRUE(report) << run.node << ": " << why;
    ASSERT_EQ(report->cases.size(), cases.size()) << run.node;
    EXPECT_EQ(report->type, spec->outputs[0].kind == PortKind::Fixed ? spec->outputs[0].type : Type::Vec3) << run.node;
    EXPECT_TRUE(report->passed()) << run.node << " " << run.options.dump() << "\n" << formatProbeText(*report);
    ++probed;
  }
  EXPECT_EQ(probed, 33);  // the 31 nodes, compare and select with two comparisons each
}

INSTANTIATE_TEST_SUITE_P(Targets, MathVocabularyOnGpu, ::testing::Values(Target::Glsl330, Target::Es300),
                         [](const auto& info) { return std::string(targetName(info.param)); });

}  // namespace
}  // namespace wg::accuracy
