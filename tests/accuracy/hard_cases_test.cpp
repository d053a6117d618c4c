// The hard-case suite (tests/hardcases/suite.json) on the GL runtime, both targets: every
// case against every node that takes such an input, every option variant and output,
// GPU float32 against the double reference. Zero NaN/Inf, every result within the node's
// documented tolerance; a failure names the node, variant, output and case.
#include <cmath>
#include <filesystem>
#include <set>

#include <gtest/gtest.h>

#include "accuracy/hard_case_suite.h"
#include "nodes/registry.h"
#include "runtime/egl_context.h"
#include "suite_file.h"
#include "test_support.h"

namespace wg::accuracy {
namespace {

using test_suite::loadSuite;

TEST(HardCaseSuite, HasAtLeastThirtyNamedCasesEachWithItsExpectation) {
  ProbeCaseFile suite = loadSuite();
  EXPECT_GE(suite.cases.size(), 30u);
  for (const auto& c : suite.cases) EXPECT_FALSE(c.expect.empty()) << c.name;
}

// A case that reaches no node would pass without testing anything.
TEST(HardCaseSuite, EveryCaseReachesSomeNode) {
  ProbeCaseFile suite = loadSuite();
  std::set<std::string> reached;
  for (const NodeSpec* spec : defaultRegistry().all()) {
    std::vector<std::string> reads = nodeReads(*spec);
    for (const auto& c : suite.cases) {
      if (!c.nodes.empty() && std::find(c.nodes.begin(), c.nodes.end(), spec->type) == c.nodes.end()) continue;
      bool applies = false;
      for (const auto& [port, v] : c.inputs) applies |= spec->inputIndex(port) >= 0;
      for (const auto& key : reads) applies |= c.given.count(key) > 0;
      if (applies) reached.insert(c.name);
    }
  }
  for (const auto& c : suite.cases) EXPECT_TRUE(reached.count(c.name)) << "case '" << c.name << "' reaches no node";
}

class HardCasesOnGpu : public ::testing::TestWithParam<Target> {};

TEST_P(HardCasesOnGpu, FiniteAndWithinEveryNodesTolerance) {
  ProbeCaseFile suite = loadSuite();
  Target target = GetParam();
  auto context = rt::EglContext::create(target == Target::Es300 ? rt::GlApi::Es32 : rt::GlApi::DesktopGl45);
  SuiteResult r = runHardCaseSuite(suite, target, SuiteOptions{});
  for (const auto& e : r.errors) ADD_FAILURE() << e;
  for (const auto& f : r.failureLines) ADD_FAILURE() << f;
  EXPECT_EQ(r.nanInf, 0);
  EXPECT_EQ(r.failures, 0);
  // Every registered node with inputs or builtins was probed.
  std::set<std::string> probed;
  for (const auto& run : r.runs) probed.insert(run.node);
  for (const char* node : {"fresnel", "refract_dir", "gerstner_waves", "voronoi", "voronoi_caustics", "hash", "fbm", "ssr",
                           "linearize_depth", "water_depth", "scene_depth", "underwater", "pow", "smoothstep", "absorption",
                           "depth_tint", "normal_map_scroll", "normal_from_height", "flow_map", "trochoid_wave"})
    EXPECT_TRUE(probed.count(node)) << node << " was not probed";
  EXPECT_GE(probed.size(), 50u);
  EXPECT_GT(r.caseRuns, 1000);
  std::printf("[ suite    ] %s: %d case runs over %zu nodes, %d failures\n", std::string(targetName(target)).c_str(),
              r.caseRuns, probed.size(), r.failures);
}

// With derived uniforms (--derived-uniforms): the per-draw parts of each node that has them
// (scroll phases, near and near/far, the camera axis) are computed per case in double, as the
// runtime computes them per draw, and the rest on the GPU; the node still meets its
// tolerance on every case, with no NaN/Inf. The identity edit of "u_derived0" counts the
// runs whose probe shader reads a derived uniform: each node must have some, or the case
// would pass without the path it names (runs whose shader reads none are the suite's own and
// left out here). linearize_depth is not in the list: alone, its near/far ratio is one
// operation per pixel, below what the planner takes out; water_depth, with two
// linearisations sharing it, is.
TEST_P(HardCasesOnGpu, NodesWithPerDrawPartsPassWithDerivedUniforms) {
  ProbeCaseFile suite = loadSuite();
  Target target = GetParam();
  auto context = rt::EglContext::create(target == Target::Es300 ? rt::GlApi::Es32 : rt::GlApi::DesktopGl45);
  for (const char* node : {"dudv_distortion", "normal_map_scroll", "flow_map", "scene_depth", "underwater",
                           "water_depth"}) {
    SCOPED_TRACE(node);
    SuiteOptions options;
    options.nodes = {node};
    options.derive = true;
    options.mutation = {"u_derived0", "u_derived0"};
    SuiteResult r = runHardCaseSuite(suite, target, options);
    for (const auto& e : r.errors) ADD_FAILURE() << e;
    for (const auto& f : r.failureLines) ADD_FAILURE() << f;
    EXPECT_EQ(r.nanInf, 0);
    EXPECT_EQ(r.failures, 0);
    EXPECT_GT(r.caseRuns, 0);
    EXPECT_GE(r.mutatedRuns, 1) << "no probe shader of " << node << " reads a derived uniform";
    std::printf("[ derived  ] %s %s: %d case runs, %d runs read derived uniforms\n",
                std::string(targetName(target)).c_str(), node, r.caseRuns, r.mutatedRuns);
  }
}

INSTANTIATE_TEST_SUITE_P(Targets, HardCasesOnGpu, ::testing::Values(Target::Glsl330, Target::Es300),
                         [](const auto& info) { return std::string(targetName(info.param)); });

}  // namespace
}  // namespace wg::accuracy
