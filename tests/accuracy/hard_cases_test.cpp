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

INSTANTIATE_TEST_SUITE_P(Targets, HardCasesOnGpu, ::testing::Values(Target::Glsl330, Target::Es300),
                         [](const auto& info) { return std::string(targetName(info.param)); });

}  // namespace
}  // namespace wg::accuracy
