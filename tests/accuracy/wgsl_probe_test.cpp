// `probe --target wgsl`: the probe plan's WGSL module (codegen/emit_wgsl.h emitWgslProbe) run
// in headless Chromium's WebGPU on SwiftShader by clients/webgpu/executor_server.mjs, each case
// one pixel read back and held to the double reference within the same bounds as the GLSL
// targets (accuracy/error_bound.h). One Chromium per test (its start takes seconds): nodes of
// the hard-case suite and every example graph the probe can run, then a wrong constant in
// the WGSL that must fail. Skipped, with the reason, without Node.js or Chromium; the paths
// where the probe cannot run are tested apart and never pass.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>

#include "accuracy/gpu_executor.h"
#include "accuracy/hard_case_suite.h"
#include "accuracy/probe.h"
#include "core/graph_load.h"
#include "runtime/runtime_error.h"
#include "sampler_test_texture.h"
#include "suite_file.h"
#include "texture_sample_cases.h"
#include "test_support.h"
#include "webgpu_client_test_base.h"

namespace wg::accuracy {
namespace {

WebgpuTools wgslProbeTools() { return {test::nodeOnPath(), test::sourcePath("clients/webgpu")}; }

class WgslProbe : public test::WebgpuClientTest {};

// Nodes whose WGSL differs most from a line-for-line copy of their GLSL: mod becomes a
// helper (WGSL's % truncates), the trochoid's ray march and ssr sample in loops
// (textureSampleLevel), 2D and cube scene textures through unfilterable bindings, a node
// texture uploaded as the runtime uploads it, integer hashing, the waves' uniforms of every
// size, and a constant the mutation below edits.
const std::vector<std::string> kWgslProbeNodes = {"fresnel", "gerstner_waves", "trochoid_wave", "ssr",
                                                  "water_depth", "cubemap_reflection", "normal_map_scroll",
                                                  "voronoi", "hash", "mod", "texture_sample"};

TEST_F(WgslProbe, NodesAndExampleGraphsAgreeWithTheDoubleReference) {
  needChromium();
  auto executor = makeWgslExecutor(wgslProbeTools());
  EXPECT_EQ(executor->targetLabel(), "wgsl");
  SuiteOptions options;
  options.nodes = kWgslProbeNodes;
  SuiteResult r = runHardCaseSuite(test_suite::loadSuite(), *executor, options);
  for (const auto& e : r.errors) ADD_FAILURE() << e;
  for (const auto& f : r.failureLines) ADD_FAILURE() << f;
  EXPECT_EQ(r.nanInf, 0);
  std::set<std::string> probed;
  double worst = 0;
  for (const auto& run : r.runs) {
    probed.insert(run.node);
    EXPECT_EQ(run.report.target, "wgsl");
    for (const auto& c : run.report.cases) worst = std::max(worst, c.bound > 0 ? c.absError / c.bound : 0.0);
  }
  for (const auto& node : kWgslProbeNodes) EXPECT_TRUE(probed.count(node)) << node << " was not probed";
  EXPECT_GT(r.caseRuns, 200);
  std::printf("[ wgsl     ] %zu nodes: %d case runs, %d failures, %d NaN/Inf, worst error/bound %.3g (%s)\n", probed.size(),
              r.caseRuns, r.failures, r.nanInf, worst, executor->deviceName().c_str());

  // Every example graph with a WGSL form, at the whole-graph hard cases. open_ocean's readers
  // are probed below (its whole graph replays the foam at each case's time: 50 s of SwiftShader).
  Diagnostics diags;
  auto cases = loadProbeCases(test::sourcePath("tests/hardcases/graphs.json"), diags);
  ASSERT_TRUE(cases);
  int graphs = 0;
  for (const auto& path : test::exampleGraphs()) {
    if (test::holdsGlslFunction(path) || std::filesystem::path(path).stem() == "open_ocean") continue;
    auto graph = loadGraphFile(path, diags);
    ASSERT_TRUE(graph) << path;
    std::optional<ProbeReport> report = probeGraph(*graph, {}, *cases, *executor, diags);
    ASSERT_TRUE(report) << path;
    ++graphs;
    double graphWorst = 0;
    for (const auto& c : report->cases) {
      EXPECT_TRUE(c.passed()) << path << " case " << c.name << ": " << c.failure();
      graphWorst = std::max(graphWorst, c.bound > 0 ? c.absError / c.bound : 0.0);
    }
    std::printf("[ wgsl     ] %s: %zu cases, %d failed, worst error/bound %.3g\n", graph->file.c_str(), report->cases.size(),
                report->failures(), graphWorst);
  }
  EXPECT_GE(graphs, 8);
}

// The mutation is made in the WGSL module itself: fresnel's water index 1.333 (the f32
// literal as the translator prints it) off by 1e-4 is outside the node's bound at normal
// incidence, where the reflectance is ((n - 1) / (n + 1))^2.
TEST_F(WgslProbe, AWrongConstantInTheWgslFails) {
  needChromium();
  auto executor = makeWgslExecutor(wgslProbeTools());
  SuiteOptions options;
  options.nodes = {"fresnel"};
  options.mutation = {"1.333", "1.3331"};
  SuiteResult r = runHardCaseSuite(test_suite::loadSuite(), *executor, options);
  EXPECT_GT(r.mutatedRuns, 0) << "1.333 is in none of fresnel's WGSL probe modules";
  EXPECT_GT(r.failures, 0) << "a wrong refractive index passed the probe";
}

// The spectral ocean's readers on WebGPU: the page simulates the ocean a probe module reads
// with the runner's own simulation (watergraph-webgpu-ocean.js: the runtime's pass shaders
// through naga) at each case's time, and binds its maps as the runner does; the filtered
// reader's pyramids and the vertex stage's bicubic read, every hard case within the node's
// bound. A Catmull-Rom weight of 2.4 for 2.5 in the WGSL must fail: the cases read maps that
// vary.
TEST_F(WgslProbe, TheOceanReadersReadTheSimulatedMaps) {
  needChromium();
  auto executor = makeWgslExecutor(wgslProbeTools());
  SuiteOptions options;
  options.nodes = {"ocean_surface", "ocean_displacement"};
  SuiteResult r = runHardCaseSuite(test_suite::loadSuite(), *executor, options);
  for (const auto& e : r.errors) ADD_FAILURE() << e;
  for (const auto& f : r.failureLines) ADD_FAILURE() << f;
  EXPECT_EQ(r.nanInf, 0);
  std::set<std::string> probed;
  for (const auto& run : r.runs) probed.insert(run.node);
  EXPECT_EQ(probed, (std::set<std::string>{"ocean_surface", "ocean_displacement"}));
  EXPECT_GT(r.caseRuns, 100);
  std::printf("[ wgsl     ] ocean readers: %d case runs, %d failures (%s)\n", r.caseRuns, r.failures,
              executor->deviceName().c_str());

  options.nodes = {"ocean_displacement"};
  options.mutation = {"2.5 * t2", "2.4 * t2"};
  SuiteResult mutated = runHardCaseSuite(test_suite::loadSuite(), *executor, options);
  EXPECT_GT(mutated.mutatedRuns, 0) << "the Catmull-Rom weight is in none of ocean_displacement's WGSL probe modules";
  EXPECT_GT(mutated.failures, 0) << "a wrong Catmull-Rom weight passed the probe";
}

// A mipmapped node texture: the runner draws its chain (WebGPU makes none) and samples it
// trilinear; the cases' uv gradients select levels 0 to 4 and blends between them (the probe
// draws uv varying by the gradient across the pixel's quad, as on GL: TextureSampleOnGpu),
// each colour space, against the double reference's box-filtered levels within the node's bound.
TEST_F(WgslProbe, AMipmappedTextureAgreesAtEveryLevel) {
  needChromium();
  auto executor = makeWgslExecutor(wgslProbeTools());
  const std::string dir = test::makeTempDir("wg_wgsl_mipmapped_");
  test::writeFile(dir + "/scrambled.png", test::scrambledPng());
  Diagnostics diags;
  auto cases = parseProbeCases(test::textureSampleCasesJson(true), "cases.json", diags);
  ASSERT_TRUE(cases);
  for (const char* space : {"srgb", "linear"}) {
    nlohmann::json options = {{"texture", "scrambled.png"}, {"wrap", "repeat"}, {"filter", "mipmapped"}, {"color_space", space}};
    test::writeFile(dir + "/g.json", test::graphJson("{\"id\": \"n\", \"type\": \"texture_sample\", \"options\": " +
                                                         options.dump() + "}",
                                                     "\"fragment\": {\"color\": \"n.rgb\"}"));
    auto graph = loadGraphFile(dir + "/g.json", diags);
    ASSERT_TRUE(graph);
    auto report = probeGraph(*graph, ProbeOutput{"n", "rgba"}, *cases, *executor, diags);
    ASSERT_TRUE(report) << options.dump();
    ASSERT_EQ(report->cases.size(), cases->cases.size());
    EXPECT_TRUE(report->passed()) << options.dump() << "\n" << formatProbeText(*report);
    const double worst = test::worstAbsError(*report);
    std::printf("[ wgsl     ] texture_sample %s: worst |gpu - ref| %.5f (%.2f 8-bit levels)\n", options.dump().c_str(), worst,
                worst * 255);
  }
  std::filesystem::remove_all(dir);
}

// Without what it needs the probe does not run, says why, and exits 2 as a missing GL context
// does: never a pass.
TEST_F(WgslProbe, SaysWhyItDidNotRun) {
  const std::string probe = "probe --node fresnel --cases " + test::shellQuote(test::sourcePath("tests/hardcases/suite.json")) +
                            " --target wgsl";
  test::CmdResult noNode = test::runSplit("env PATH=/nonexistent " + test::shellQuote(test::watergraphBinary()) + " " + probe);
  EXPECT_EQ(noNode.exit, 2) << noNode.out << noNode.err;
  EXPECT_NE(noNode.err.find("did not run on wgsl: Node.js (node) is not on PATH"), std::string::npos) << noNode.err;
  EXPECT_EQ(noNode.out.find("cases passed"), std::string::npos) << noNode.out;

  const std::filesystem::path empty = std::filesystem::temp_directory_path() / "wg_wgsl_probe_no_client";
  std::filesystem::create_directories(empty);
  test::CmdResult noPackages =
      test::runSplit("env WATERGRAPH_WEBGPU_CLIENT=" + test::shellQuote(empty.string()) + " " +
                     test::shellQuote(test::watergraphBinary()) + " " + probe);
  EXPECT_EQ(noPackages.exit, 2) << noPackages.out << noPackages.err;
  EXPECT_NE(noPackages.err.find("the npm package playwright-core is not installed"), std::string::npos) << noPackages.err;
  std::filesystem::remove_all(empty);

  // No Chromium: the helper says so before any probe and the executor is not made.
  WebgpuTools tools = wgslProbeTools();
  tools.chromium = "/nonexistent/chromium";
  try {
    makeWgslExecutor(tools);
    ADD_FAILURE() << "a WebGPU executor was made without Chromium";
  } catch (const rt::RuntimeError& e) {
    EXPECT_EQ(e.kind(), rt::RuntimeError::Kind::Environment);
    EXPECT_NE(std::string(e.what()).find("no Chromium at /nonexistent/chromium"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace wg::accuracy
