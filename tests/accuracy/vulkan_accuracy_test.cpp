// `probe` and `check` on vk450: the probe shaders and the water's SPIR-V run on Vulkan
// (lavapipe) through the Vulkan executor (accuracy/gpu_executor.h), every run under the
// Khronos validation layer, which turns any message into an error. The hard-case suite
// passes there as on GL; node probes give GL's values within the error bound; check of
// example graphs on vk450 (the spectral ocean's open_ocean too) is finite and within the
// CPU reference's bound; the CLI takes
// --target vk450 --vk-validation for probe (graph, node and sweep modes) and check.
#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "accuracy/check.h"
#include "accuracy/gpu_executor.h"
#include "accuracy/hard_case_suite.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "suite_file.h"
#include "test_support.h"

namespace wg::accuracy {
namespace {

std::unique_ptr<GpuExecutor> validatingVulkan() {
  ExecutorOptions o;
  o.vulkanValidation = true;
  o.tessellation = true;
  return makeGpuExecutor(Target::Vk450, o);
}

bool readsOcean(const NodeSpec& spec) {
  for (const PortSpec& p : spec.inputs)
    if (p.kind == PortKind::Fixed && p.type == Type::Ocean) return true;
  return false;
}

std::string runWatergraph(const std::string& args, int* rc) {
  std::string out;
  *rc = test::runCommand(test::shellQuote(test::watergraphBinary()) + " " + args, &out);  // stderr too
  return out;
}

// Every node the suite reaches, every option variant and output, on vk450 under the layer.
TEST(VulkanProbe, TheHardCaseSuitePassesUnderValidation) {
  ProbeCaseFile suite = test_suite::loadSuite();
  auto vk = validatingVulkan();
  // The ocean readers simulate their seas for each case's time: their own test below
  // (VulkanProbe.TheOceanReadersPassTheirHardCasesUnderValidation).
  SuiteOptions options;
  for (const NodeSpec* spec : defaultRegistry().all())
    if (!readsOcean(*spec)) options.nodes.push_back(spec->type);
  SuiteResult r = runHardCaseSuite(suite, *vk, options);
  vk->finish();
  for (const auto& e : r.errors) ADD_FAILURE() << e;
  for (const auto& f : r.failureLines) ADD_FAILURE() << f;
  EXPECT_EQ(r.nanInf, 0);
  EXPECT_EQ(r.failures, 0);
  std::set<std::string> probed;
  for (const auto& run : r.runs) {
    probed.insert(run.node);
    EXPECT_EQ(run.report.target, "vk450");
  }
  // Uniform-only nodes, 2D and cube scene textures, node textures: every kind of binding.
  for (const char* node : {"fresnel", "gerstner_waves", "scene_depth", "ssr", "cubemap_reflection", "normal_map_scroll",
                           "underwater", "fbm"})
    EXPECT_TRUE(probed.count(node)) << node << " was not probed on vk450";
}

// The ocean readers' hard cases (t = 1e6 s among them), their maps simulated by the
// Vulkan runtime at each case's time: within their bounds, no NaN/Inf, as on GL. The
// surface and the displacement (the slope and displacement maps, about 13 s on lavapipe);
// ocean_foam's cases replay the foam at each of their times (120 s on lavapipe, 84 s on
// llvmpipe), too long for CI: `watergraph probe --node ocean_foam --cases
// tests/hardcases/suite.json --target vk450 --vk-validation` runs them (0 failed), and
// VkOcean.FoamMatchesTheReplayedReferenceWithinItsBound holds the Vulkan foam to its bound.
TEST(VulkanProbe, TheOceanReadersPassTheirHardCasesUnderValidation) {
  ProbeCaseFile suite = test_suite::loadSuite();
  auto vk = validatingVulkan();
  SuiteOptions options;
  options.nodes = {"ocean_surface", "ocean_displacement"};
  for (const std::string& node : options.nodes) ASSERT_TRUE(readsOcean(*defaultRegistry().find(node))) << node;
  SuiteResult r = runHardCaseSuite(suite, *vk, options);
  vk->finish();
  for (const auto& e : r.errors) ADD_FAILURE() << e;
  for (const auto& f : r.failureLines) ADD_FAILURE() << f;
  EXPECT_EQ(r.nanInf, 0);
  EXPECT_EQ(r.failures, 0);
  std::set<std::string> probed;
  for (const auto& run : r.runs) probed.insert(run.node);
  for (const std::string& node : options.nodes) EXPECT_TRUE(probed.count(node)) << node << " was not probed on vk450";
}

// The same cases on both APIs: the float32 results agree within each case's error bound
// (the probe's: tolerance * max(1, |ref|) + conditioning), and so do the NaN/Inf flags.
// The nodes cover uniforms of every size at their std140 offsets (vec3 after float, time
// phases), 2D and cube scene textures and a node texture at their bindings.
TEST(VulkanProbe, NodeProbesMatchGlWithinTheBound) {
  ProbeCaseFile suite = test_suite::loadSuite();
  SuiteOptions options;
  options.nodes = {"fresnel", "gerstner_waves", "scene_depth", "ssr", "cubemap_reflection", "normal_map_scroll"};
  SuiteResult gl = runHardCaseSuite(suite, *makeGpuExecutor(Target::Glsl330), options);
  auto executor = validatingVulkan();
  SuiteResult vk = runHardCaseSuite(suite, *executor, options);
  executor->finish();
  for (const auto& e : vk.errors) ADD_FAILURE() << e;
  ASSERT_EQ(vk.runs.size(), gl.runs.size());
  ASSERT_GE(vk.runs.size(), options.nodes.size());
  int compared = 0;
  for (size_t i = 0; i < vk.runs.size(); ++i) {
    const ProbeReport& a = gl.runs[i].report;
    const ProbeReport& b = vk.runs[i].report;
    ASSERT_EQ(a.output, b.output);
    ASSERT_EQ(a.cases.size(), b.cases.size()) << a.output;
    for (size_t k = 0; k < a.cases.size(); ++k) {
      const ProbeCaseResult& x = a.cases[k];
      const ProbeCaseResult& y = b.cases[k];
      EXPECT_EQ(x.gpuFinite, y.gpuFinite) << b.output << " case " << y.name;
      for (int c = 0; c < y.components && x.gpuFinite; ++c) {
        auto at = static_cast<size_t>(c);
        double bound = y.tolerance * std::max(1.0, std::abs(y.reference[at])) + y.conditioning;
        EXPECT_LE(std::abs(y.gpu[at] - x.gpu[at]), bound)
            << vk.runs[i].variant << " " << b.output << " case " << y.name << " component " << c << ": vk450 " << y.gpu[at]
            << ", glsl330 " << x.gpu[at];
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 100);
}

// Two example graphs through check on vk450 under the layer: the compile's SPIR-V drawn
// over the whole sweep, no NaN/Inf, every sampled pixel compared with the CPU reference on
// its read-back inputs (tap shaders compiled to SPIR-V) within its bound. The pool reads
// back scene depth and colour; the ocean's vertex stage displaces the surface.
TEST(VulkanCheck, ExampleGraphsAreWithinTheirBoundsUnderValidation) {
  auto vk = validatingVulkan();
  for (const char* name : {"pool", "ocean"}) {
    std::string path = test::sourcePath(std::string("graphs/") + name + ".json");
    Diagnostics diags;
    auto graph = loadGraphFile(path, diags);
    ASSERT_TRUE(graph) << path;
    CompileOptions co;
    co.targets = {Target::Vk450};
    auto result = compileGraph(*graph, defaultRegistry(), co, diags);
    ASSERT_TRUE(result) << path;
    CheckOptions options;
    options.width = 48;
    options.height = 27;
    CheckReport r = checkGraph(*result, path, *vk, options);
    EXPECT_EQ(r.reference, "cpu") << name;
    EXPECT_EQ(r.nanInf(), 0) << formatCheckText(r);
    EXPECT_GT(r.samples(), 50) << formatCheckText(r);
    EXPECT_EQ(r.overBound(), 0) << formatCheckText(r);
    EXPECT_LT(r.maxError(), 1e-3) << formatCheckText(r);
  }
  vk->finish();
}

// The spectral ocean through check on vk450 under the layer: open_ocean (three 256^2
// cascades, the slopes and two cascades' foam read) simulated by the Vulkan runtime over
// the whole sweep, t = 1e6 s included: no NaN/Inf, every sampled pixel within the CPU
// reference's bound, as on glsl330 (CheckCli.EveryExampleGraphIsWithinItsBound).
TEST(VulkanCheck, OpenOceanIsFiniteAndWithinItsBoundUnderValidation) {
  auto vk = validatingVulkan();
  const std::string path = test::sourcePath("graphs/open_ocean.json");
  Diagnostics diags;
  auto graph = loadGraphFile(path, diags);
  ASSERT_TRUE(graph) << path;
  CompileOptions co;
  co.targets = {Target::Vk450};
  auto result = compileGraph(*graph, defaultRegistry(), co, diags);
  ASSERT_TRUE(result) << path;
  ASSERT_FALSE(result->manifest.oceans.empty());
  CheckOptions options;
  options.width = 48;
  options.height = 27;
  CheckReport r = checkGraph(*result, path, *vk, options);
  EXPECT_EQ(r.reference, "cpu");
  EXPECT_EQ(r.nanInf(), 0) << formatCheckText(r);
  EXPECT_GT(r.samples(), 50) << formatCheckText(r);
  EXPECT_EQ(r.overBound(), 0) << formatCheckText(r);
  EXPECT_LT(r.maxError(), 1e-3) << formatCheckText(r);
  vk->finish();
}

// As a user runs them: probe in graph, node and sweep modes and check, on vk450 with the
// layer; deferred_underwater compared with the CPU as on GL.
TEST(VulkanCli, ProbeAndCheckTakeTheVk450Target) {
  int rc = 0;
  std::string out = runWatergraph("probe " + test::shellQuote(test::sourcePath("graphs/lake.json")) + " --cases " +
                                      test::shellQuote(test::sourcePath("tests/hardcases/graphs.json")) +
                                      " --target vk450 --vk-validation",
                                  &rc);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_NE(out.find("on vk450"), std::string::npos) << out;
  out = runWatergraph("probe --node fresnel --cases " + test::shellQuote(test::sourcePath("tests/hardcases/suite.json")) +
                          " --target vk450 --vk-validation",
                      &rc);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_NE(out.find(" 0 failed"), std::string::npos) << out;
  out = runWatergraph("probe --node fresnel --sweep angle:0:90:200 --target vk450 --vk-validation", &rc);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_NE(out.find("on vk450: 200 points, 0 over the bound"), std::string::npos) << out;
  out = runWatergraph("check " + test::shellQuote(test::sourcePath("graphs/deferred_underwater.json")) +
                          " --target vk450 --vk-validation --size 16x9",
                      &rc);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_NE(out.find("on vk450"), std::string::npos) << out;
  EXPECT_NE(out.find("reference: cpu"), std::string::npos) << out;
  EXPECT_NE(out.find("over the bound 0\n"), std::string::npos) << out;
  // Validation is a Vulkan matter: asked of a GL target it is a usage error.
  out = runWatergraph("probe --node fresnel --sweep angle:0:90:10 --target glsl330 --vk-validation", &rc);
  EXPECT_EQ(rc, 2) << out;
  EXPECT_NE(out.find("--vk-validation needs --target vk450"), std::string::npos) << out;
}

}  // namespace
}  // namespace wg::accuracy
