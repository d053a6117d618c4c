// watergraph check on every graph in graphs/ (globbed, so new example graphs are checked
// as they arrive), both targets, at 160x90: no NaN or Inf pixel anywhere in the sweep;
// graphs with a full CPU reference agree with it on the sampled water pixels. The CLI's
// exit status: 0 for the examples, 1 for a graph that renders NaN.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "accuracy/check.h"
#include "codegen/compile.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "runtime/egl_context.h"
#include "runtime/preview.h"
#include "test_support.h"

namespace wg::accuracy {
namespace {

std::optional<CompileResult> compileFor(const std::string& path, Target target) {
  Diagnostics diags;
  auto graph = loadGraphFile(path, diags);
  if (!graph) return std::nullopt;
  CompileOptions o;
  o.targets = {target};
  return compileGraph(*graph, defaultRegistry(), o, diags);
}

TEST(CheckSweep, CoversGrazingToTopDownTimesSunsAndUnderWater) {
  auto views = checkSweep(false);
  float lowest = 90, highest = 0;
  for (const auto& v : views) {
    glm::vec3 d = glm::normalize(v.camera.position - v.camera.target);
    float elevation = glm::degrees(std::asin(d.y));
    lowest = std::min(lowest, elevation), highest = std::max(highest, elevation);
  }
  EXPECT_LT(lowest, 1.0f);
  EXPECT_GT(highest, 89.0f);
  bool bigTime = false;
  for (const auto& v : views) bigTime |= v.scene.time >= 1e6f;
  EXPECT_TRUE(bigTime);
  auto under = checkSweep(true);
  ASSERT_GT(under.size(), views.size());
  EXPECT_LT(under.back().camera.position.y, 0.0f);
}

class CheckOnGpu : public ::testing::TestWithParam<Target> {};

TEST_P(CheckOnGpu, EveryExampleGraphIsFiniteOverTheSweep) {
  Target target = GetParam();
  auto context = rt::EglContext::create(rt::apiFor(target));
  auto graphs = test::exampleGraphs();
  ASSERT_FALSE(graphs.empty());
  int compared = 0;
  for (const auto& path : graphs) {
    SCOPED_TRACE(path);
    auto result = compileFor(path, target);
    ASSERT_TRUE(result);
    CheckReport r = checkGraph(*result, path, target, 160, 90);
    EXPECT_EQ(r.nanInf(), 0) << formatCheckText(r);
    if (r.reference == "cpu") {
      int samples = 0;
      for (const auto& v : r.views) samples += v.referenceSamples;
      EXPECT_GT(samples, 50) << formatCheckText(r);
      // float32 colour against the double reference: 1e-3 is a quarter of an 8-bit step.
      EXPECT_LT(r.maxError(), 1e-3) << formatCheckText(r);
      ++compared;
    }
  }
  if (target == Target::Glsl330) {
    EXPECT_GE(compared, 1) << "no example graph was compared with its CPU reference";
  }
}

INSTANTIATE_TEST_SUITE_P(Targets, CheckOnGpu, ::testing::Values(Target::Glsl330, Target::Es300),
                         [](const auto& info) { return std::string(targetName(info.param)); });

TEST(CheckCli, ExitsOneOnNanPixels) {
  std::string dir = test::makeTempDir("wg_check");
  std::string graph = dir + "/nan.json";
  test::writeFile(graph, R"({"version": 1, "name": "nan", "nodes": [{"id": "q", "type": "div", "inputs": {"a": 0, "b": 0}}],
    "outputs": {"fragment": {"color": "q.out"}}})");
  std::string out;
  int rc = test::runCommand(test::shellQuote(test::watergraphBinary()) + " check " + test::shellQuote(graph) +
                                " --target glsl330 --size 32x18",
                            &out);
  EXPECT_EQ(rc, 1) << out;
  EXPECT_NE(out.find("FAIL"), std::string::npos) << out;
  rc = test::runCommand(test::shellQuote(test::watergraphBinary()) + " check " +
                            test::shellQuote(test::sourcePath("graphs/lake.json")) + " --target es300 --size 32x18",
                        &out);
  EXPECT_EQ(rc, 0) << out;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace wg::accuracy
