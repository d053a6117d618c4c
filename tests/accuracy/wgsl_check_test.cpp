// `check --target wgsl`: a graph's GRAPH.wgsl and its read-back tap modules
// (codegen/readback_taps.h emitTapModuleWgsl) drawn by the WebGPU runner in headless
// Chromium's WebGPU on SwiftShader (accuracy/wgsl_water_frames.h), every sampled water pixel
// held to the double reference on the inputs read back, within the same bounds as on glsl330
// and vk450. One Chromium per test (its start takes seconds): the API test checks a graph and
// a graph with a wrong node in its WGSL; the CLI test checks a graph it passes and one with
// no WGSL form (exit 1, the node named). Skipped, with the reason, without
// Node.js or Chromium; without them check says it did not run and exits 2.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "accuracy/check.h"
#include "accuracy/gpu_executor.h"
#include "codegen/compile.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "runtime/runtime_error.h"
#include "test_support.h"
#include "webgpu_client_test_base.h"

namespace wg::accuracy {
namespace {

class WgslCheck : public test::WebgpuClientTest {};

std::optional<CompileResult> compileForWgsl(const std::string& path) {
  Diagnostics diags;
  auto graph = loadGraphFile(path, diags);
  if (!graph) return std::nullopt;
  CompileOptions o;
  o.targets = {Target::Es300};
  o.wgsl = true;
  return compileGraph(*graph, defaultRegistry(), o, diags);
}

// The ocean: forward water reading the environment cube and a node texture, both look-ups
// read back through a WGSL tap module; then, on the same executor, the lake with a wrong node
// in its WGSL (its Schlick F0 0.02 -> 0.0201, as CheckCli.FailsWhenANodeIsWrong on glsl330),
// which must fail.
TEST_F(WgslCheck, AGraphAgreesWithTheDoubleReferenceAndAWrongNodeFails) {
  needChromium();
  auto executor = makeWgslExecutor({test::nodeOnPath(), test::sourcePath("clients/webgpu")});
  CheckOptions options;
  options.width = 48;
  options.height = 27;
  options.errorMaps = true;  // every water pixel compared, and where each lies
  const std::string ocean = test::sourcePath("graphs/ocean.json");
  auto result = compileForWgsl(ocean);
  ASSERT_TRUE(result);
  CheckReport report = checkGraph(*result, ocean, *executor, options);
  EXPECT_EQ(report.targetLabel, "wgsl");
  EXPECT_EQ(report.reference, "cpu");
  EXPECT_EQ(report.nanInf(), 0);
  EXPECT_EQ(report.overBound(), 0) << formatCheckText(report);
  EXPECT_GT(report.samples(), 2000) << formatCheckText(report);
  EXPECT_NE(formatCheckText(report).find("on wgsl, 48x27"), std::string::npos) << formatCheckText(report);
  // The frame's rows as check's other targets hold them (top to bottom): seen from 10 degrees
  // above, the water, where pixels are compared, fills the frame below the horizon.
  for (const CheckViewResult& v : report.views) {
    if (v.label != "elevation 10 deg") continue;
    double rows = 0, compared = 0;
    for (size_t i = 0; i < v.ratios.size(); ++i)
      if (v.ratios[i] >= 0) rows += static_cast<double>(i / static_cast<size_t>(options.width)), ++compared;
    ASSERT_GT(compared, 0);
    EXPECT_GT(rows / compared, options.height / 2.0) << "the water is not in the lower half of the frame";
  }
  std::printf("[ wgsl     ] ocean: %d px compared, worst error/bound %.3g, max %.2e (%s)\n", report.samples(),
              report.worstRatio(), report.maxError(), executor->deviceName().c_str());

  const std::string lake = test::sourcePath("graphs/lake.json");
  auto lakeResult = compileForWgsl(lake);
  ASSERT_TRUE(lakeResult);
  options.errorMaps = false;
  options.mutation = {"wg_fresnel_schlick(n8_fresnel_t0, 0.02)", "wg_fresnel_schlick(n8_fresnel_t0, 0.0201)"};
  CheckReport wrong = checkGraph(*lakeResult, lake, *executor, options);
  EXPECT_GT(wrong.overBound(), 0) << "a wrong Fresnel F0 in the WGSL passed check\n" << formatCheckText(wrong);
  EXPECT_TRUE(wrong.failed());
}

// The CLI, one Chromium for the three graphs: the lake passes, and so does a graph sampling a
// node texture through its mipmaps (the runner makes the chain); caustic_pool, whose
// glsl_function node has no WGSL form, is an error at that node (exit 1), never a pass.
TEST_F(WgslCheck, TheCliPassesAGraphAndNamesWhatItCannotCheck) {
  needChromium();
  const std::string mipmapped = test::sourcePath("tests/ecosystem/data/mipmapped_texture.json");
  test::CmdResult r = test::runSplit(test::shellQuote(test::watergraphBinary()) + " check " +
                                     test::shellQuote(test::sourcePath("graphs/lake.json")) + " " + test::shellQuote(mipmapped) +
                                     " " + test::shellQuote(test::sourcePath("graphs/caustic_pool.json")) +
                                     " --target wgsl --size 48x27");
  EXPECT_EQ(r.exit, 1) << r.out << r.err;
  for (const std::string& graph : {test::sourcePath("graphs/lake.json"), mipmapped})
    EXPECT_NE(r.out.find("check " + graph + " on wgsl"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("reference: cpu"), std::string::npos) << r.out;
  size_t ok = 0;
  for (size_t at = r.out.find("ok: 0 NaN/Inf pixel values, 0 pixels over the error bound"); at != std::string::npos;
       at = r.out.find("ok: 0 NaN/Inf pixel values", at + 1))
    ++ok;
  EXPECT_EQ(ok, 2u) << r.out;
  EXPECT_NE(r.err.find("error: [WG045] no WGSL form (--target wgsl): a glsl_function node's file is GLSL only"), std::string::npos)
      << r.err;
  EXPECT_EQ(r.out.find("check " + test::sourcePath("graphs/caustic_pool.json")), std::string::npos) << r.out;
}

// Without what it needs check does not run, says why, and exits 2 as a missing GL context
// does: never a pass.
TEST_F(WgslCheck, SaysWhyItDidNotRun) {
  const std::string check = "check " + test::shellQuote(test::sourcePath("graphs/pool.json")) + " --target wgsl";
  test::CmdResult noNode = test::runSplit("env PATH=/nonexistent " + test::shellQuote(test::watergraphBinary()) + " " + check);
  EXPECT_EQ(noNode.exit, 2) << noNode.out << noNode.err;
  EXPECT_NE(noNode.err.find("check did not run on wgsl: Node.js (node) is not on PATH"), std::string::npos) << noNode.err;
  EXPECT_EQ(noNode.out.find("ok:"), std::string::npos) << noNode.out;

  const std::filesystem::path empty = std::filesystem::temp_directory_path() / "wg_wgsl_check_no_client";
  std::filesystem::create_directories(empty);
  test::CmdResult noPackages = test::runSplit("env WATERGRAPH_WEBGPU_CLIENT=" + test::shellQuote(empty.string()) + " " +
                                              test::shellQuote(test::watergraphBinary()) + " " + check);
  EXPECT_EQ(noPackages.exit, 2) << noPackages.out << noPackages.err;
  EXPECT_NE(noPackages.err.find("check did not run on wgsl: "), std::string::npos) << noPackages.err;
  EXPECT_NE(noPackages.err.find("is not installed"), std::string::npos) << noPackages.err;
  std::filesystem::remove_all(empty);

  // No Chromium: the helper says so and the executor is not made.
  try {
    makeWgslExecutor({test::nodeOnPath(), test::sourcePath("clients/webgpu"), "/nonexistent/chromium"});
    ADD_FAILURE() << "a WebGPU executor was made without Chromium";
  } catch (const rt::RuntimeError& e) {
    EXPECT_EQ(e.kind(), rt::RuntimeError::Kind::Environment);
    EXPECT_EQ(e.exitCode(), 2);
    EXPECT_NE(std::string(e.what()).find("no Chromium at /nonexistent/chromium"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace wg::accuracy
