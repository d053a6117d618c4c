// GRAPH.wgsl executed: clients/webgpu's runner runs every pass a graph's manifest lists (the
// scene passes with the runtime's own shaders, translated by naga; deferred water's G-buffer)
// in headless Chromium's WebGPU (SwiftShader), and each frame is compared with the GL
// runtime's glsl330 render of the same camera through clamp and the sRGB encoding
// (`render --tonemap none --exposure 0`). Every example graph with a WGSL form is rendered
// twice: with no scene drawn (`--scene none`: the passes still run, their targets cleared), where
// what differs is the graph's WGSL against its GLSL, held to the 40 dB; and in the
// built-in scene, which adds the runtime's scene on two rasterisers (the bar and why below).
// One browser renders each test's frames. Skipped (with the reason) without Node.js, Chromium
// or the GL runtime; never passed for want of them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <vector>

#include "eco_support.h"
#include "nodes/registry.h"
#ifdef WG_HAVE_RUNTIME
#include "runtime/image.h"
#endif

namespace wg::eco {
namespace {

#ifdef WG_HAVE_RUNTIME
// As the vk450 and three.js comparisons: a float path and another rasteriser agree to 40 dB.
constexpr double kWebgpuMinPsnrDb = 40.0;
constexpr const char* kRunnerSize = "320x180";

// The example graphs a WGSL form exists for (caustic_pool's glsl_function node is GLSL only,
// WG045): the water-only ones and those whose manifest lists scene passes.
const std::vector<std::string> kWaterOnlyGraphs = {"lake", "lagoon", "shelf", "topdown"};
const std::vector<std::string> kScenePassGraphs = {"classic_webgl", "deferred_underwater", "ocean", "pool",
                                                   "river", "stylized", "tutorial_pbr"};
// A spectral ocean: its simulation passes run too (watergraph-webgpu-ocean.js), with no scene
// and in the built-in scene (WebgpuRunner.TheSpectralOceanMatchesGlsl330FromTwoCameras).
const std::vector<std::string> kSpectralOceanGraphs = {"open_ocean"};
// A node texture sampled through its mipmaps, minified towards the horizon.
constexpr const char* kMipmappedTextureGraph = "tests/ecosystem/data/mipmapped_texture.json";

struct RunnerJob {
  std::string graph;   // a path under the source tree, or an absolute one
  std::string camera;  // a camera preset
  bool scene = true;   // false: `--scene none`
};

class WebgpuRunner : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!haveTool("node")) {
      skip_ = "Node.js (node) is not on PATH";
      return;
    }
    if (!std::filesystem::exists("/usr/bin/chromium")) {
      skip_ = "Debian's chromium is not installed (/usr/bin/chromium)";
      return;
    }
    // The runner takes uniform values, the grid and the pass plan from the three.js client,
    // naga-wasm and playwright-core from its own.
    for (const char* client : {"clients/webgpu", "clients/three"}) {
      CmdResult r = sh(test::shellQuote(test::sourcePath("clients/three/test/npm_ci_cached.sh")) + " " +
                       test::shellQuote(test::sourcePath(client)));
      if (r.exit != 0) npmError_ += std::string("installing ") + client + "'s npm packages failed: " + r.err;
    }
  }
  void SetUp() override {
    if (!skip_.empty()) GTEST_SKIP() << skip_;
    ASSERT_TRUE(npmError_.empty()) << npmError_;
  }

  static std::string stem(const std::string& graph) { return std::filesystem::path(graph).stem().string(); }

  // Runs render_webgpu.mjs over `jobs` (a JSON list) in one browser.
  static CmdResult runBatch(const TempDir& dir, const nlohmann::json& jobs, int timeoutSeconds) {
    test::writeFile(dir / "jobs.json", jobs.dump(1));
    return sh("timeout " + std::to_string(timeoutSeconds) + " node " +
              test::shellQuote(test::sourcePath("clients/webgpu/test/render_webgpu.mjs")) + " --dir " +
              test::shellQuote(dir.path()) + " --jobs " + test::shellQuote(dir / "jobs.json") + " --description " +
              test::shellQuote(dir / "scene.json") + " --size " + kRunnerSize + " --time 3.5 --grid 128");
  }

  // Compiles each graph once (es300 for the three.js client's uniforms, and wgsl), renders
  // each job with the runtime (glsl330) and with the WebGPU runner, and returns the PSNR in dB
  // of each job's two frames, in the jobs' order (0 where a render failed, with the failure
  // reported).
  static std::vector<double> comparedPsnrs(const std::vector<RunnerJob>& jobs) {
    TempDir dir("wg_webgpu_");
    CmdResult s = wgRun("scene -o " + test::shellQuote(dir / "scene.json"));
    EXPECT_EQ(s.exit, 0) << s.err;
    std::set<std::string> compiled;
    nlohmann::json batch = nlohmann::json::array();
    std::vector<std::string> references, frames;
    for (size_t i = 0; i < jobs.size(); ++i) {
      const RunnerJob& job = jobs[i];
      const std::string graph = std::filesystem::path(job.graph).is_absolute() ? job.graph : test::sourcePath(job.graph);
      const std::string name = stem(job.graph);
      if (compiled.insert(name).second) {
        CmdResult c = wgRun("compile " + test::shellQuote(graph) + " -o " + test::shellQuote(dir / name) +
                            " --target es300,wgsl --textures --quiet");
        EXPECT_EQ(c.exit, 0) << job.graph << ": " << c.err;
      }
      const std::string tag = std::to_string(i) + "." + name + "." + job.camera + (job.scene ? ".scene" : ".none");
      references.push_back(dir / (tag + ".glsl330.png"));
      frames.push_back(dir / (tag + ".webgpu.png"));
      CmdResult r = wgRun("render " + test::shellQuote(graph) + " -o " + test::shellQuote(references.back()) +
                          " --target glsl330 " + (job.scene ? "" : "--scene none ") +
                          "--tonemap none --exposure 0 --size " + kRunnerSize + " --camera " + job.camera +
                          " --time 3.5 --grid 128");
      EXPECT_EQ(r.exit, 0) << job.graph << ": " << r.err;
      batch.push_back({{"manifest", name + "/" + name + ".manifest.json"}, {"camera", job.camera},
                       {"png", frames.back()}, {"scene", job.scene ? "builtin" : "none"}});
    }
    CmdResult w = runBatch(dir, batch, 60 + 20 * static_cast<int>(jobs.size()));
    EXPECT_EQ(w.exit, 0) << w.out << w.err;
    std::vector<double> psnrs;
    for (size_t i = 0; i < jobs.size(); ++i) {
      if (!std::filesystem::exists(references[i]) || !std::filesystem::exists(frames[i])) {
        ADD_FAILURE() << jobs[i].graph << " " << jobs[i].camera << ": a frame is missing";
        psnrs.push_back(0);
        continue;
      }
      rt::Image a = rt::readPng(references[i]), b = rt::readPng(frames[i]);
      EXPECT_EQ(a.width, b.width);
      EXPECT_EQ(a.height, b.height);
      double psnr = a.width == b.width && a.height == b.height ? rt::psnrRgb8(a, b) : 0;
      std::printf("WebGPU (wgsl) vs runtime (glsl330), %s camera %s %s %s: PSNR %.2f dB\n", jobs[i].graph.c_str(),
                  jobs[i].camera.c_str(), jobs[i].scene ? "built-in scene" : "scene none", kRunnerSize, psnr);
      psnrs.push_back(psnr);
    }
    return psnrs;
  }

  static inline std::string skip_, npmError_;
};

// Every example graph with a WGSL form, every pass its manifest lists, no scene drawn: the
// water-only graphs (the lake's Fresnel and sRGB parameters, the lagoon's PNG through
// texture_sample, topdown's Gerstner waves in the vertex stage) and those reading scene
// resources (depth, colour copy, reflection, refraction, environment cube, deferred water's
// G-buffer, here cleared targets read through the graph's WGSL), and the spectral ocean with
// its simulation (55.75 dB above and 56.89 dB top-down since its cascades' slopes are read
// at each pixel's footprint; 31.42 and 37.26 dB when they were point-sampled, the sun's
// glints on different pixels). From above and from the top-down camera, at the bar
// of 40 dB.
TEST_F(WebgpuRunner, EveryExampleGraphMatchesGlsl330WithNoScene) {
  std::vector<RunnerJob> jobs;
  for (const auto* list : {&kWaterOnlyGraphs, &kScenePassGraphs, &kSpectralOceanGraphs})
    for (const std::string& g : *list)
      for (const char* camera : {"above", "topdown"}) jobs.push_back({"graphs/" + g + ".json", camera, false});
  // A mipmapped node texture (no example graph has one): the runner's own mip chain
  // (WebGPU makes none) and trilinear sampler against the runtime's glGenerateMipmap.
  for (const char* camera : {"above", "topdown"}) jobs.push_back({kMipmappedTextureGraph, camera, false});
  std::vector<double> psnrs = comparedPsnrs(jobs);
  for (size_t i = 0; i < jobs.size(); ++i) EXPECT_GE(psnrs[i], kWebgpuMinPsnrDb) << jobs[i].graph << " " << jobs[i].camera;
}

// In the built-in scene the runtime's own scene shaders run on two rasterisers, and that alone
// stays under 40 dB: tests/ecosystem/data/clear_water.json (water of alpha 0, so the frame is
// the scene) measures 38.6 dB above and 39.9 dB top-down. Nearly all of it is the pool's
// procedural tiles: 2-4 cm grout lines and a checker flipping at every metre, shaded at pixel
// centres whose interpolated world positions differ in their last bits between llvmpipe and
// SwiftShader, so distant tiles alias differently (the differing pixels lie on the grout grid).
// A graph refracting or reflecting the scene moves those pixels around: the lowest, river from
// above, measures 36.8 dB (the others 37.9-41.1). The bar is the scene's, above the three.js
// client's 33 dB for the same scene (tests/ecosystem/three_client_test.cpp); what the graph's
// WGSL adds is held to 40 dB by the test above.
constexpr double kWebgpuBuiltinSceneMinPsnrDb = 35.0;
TEST_F(WebgpuRunner, ScenePassGraphsMatchGlsl330InTheBuiltInScene) {
  std::vector<RunnerJob> jobs;
  for (const char* camera : {"above", "topdown"}) jobs.push_back({"tests/ecosystem/data/clear_water.json", camera, true});
  for (const std::string& g : kScenePassGraphs)
    for (const char* camera : {"above", "topdown"}) jobs.push_back({"graphs/" + g + ".json", camera, true});
  std::vector<double> psnrs = comparedPsnrs(jobs);
  for (size_t i = 0; i < jobs.size(); ++i)
    EXPECT_GE(psnrs[i], kWebgpuBuiltinSceneMinPsnrDb) << jobs[i].graph << " " << jobs[i].camera;
}

// The spectral ocean: the runtime's simulation pass shaders translated by naga and run as
// fragment passes into float textures (its filtered cascades' slope and moments maps with
// mip pyramids), h0 and the clocks from the compiler's open_ocean.ocean.js, in the built-in
// scene from two cameras under the default sun, at the runner's bar for the built-in scene.
// Measured 39.96 dB above and 38.45 dB top-down. Before the ocean's shading was filtered
// the sun had to be below the horizon: the point-sampled centimetre waves mirrored it into
// scattered glints the two rasterisers put on different pixels (29.93 and 36.09 dB at this
// sun; tests/ecosystem/three_client_test.cpp says more).
TEST_F(WebgpuRunner, TheSpectralOceanMatchesGlsl330FromTwoCameras) {
  std::vector<RunnerJob> jobs;
  for (const std::string& g : kSpectralOceanGraphs)
    for (const char* camera : {"above", "topdown"}) jobs.push_back({"graphs/" + g + ".json", camera, true});
  std::vector<double> psnrs = comparedPsnrs(jobs);
  for (size_t i = 0; i < jobs.size(); ++i)
    EXPECT_GE(psnrs[i], kWebgpuBuiltinSceneMinPsnrDb) << jobs[i].graph << " " << jobs[i].camera;
}

// From the grazing camera the two rasterisers differ where nothing about the shader does:
// on the horizon row, where the grid's far edge runs along pixel centres (SwiftShader and
// llvmpipe break those ties differently: the lake measures 45.2 dB above and 39.98 dB here,
// all of the difference in 11 pixels of one row), and where the lagoon's texture is minified
// far without mipmaps (aliasing: 52.2 dB without the 244 pixels of rows 90-97, 37.1 dB with
// them). The bar is the three.js client's for the same view (tests/ecosystem/three_client_test.cpp).
constexpr double kWebgpuGrazingMinPsnrDb = 37.0;
TEST_F(WebgpuRunner, WaterOnlyExampleGraphsMatchGlsl330AtGrazing) {
  std::vector<RunnerJob> jobs;
  for (const std::string& g : kWaterOnlyGraphs) jobs.push_back({"graphs/" + g + ".json", "grazing", false});
  jobs.push_back({kMipmappedTextureGraph, "grazing", false});  // minified the most here
  std::vector<double> psnrs = comparedPsnrs(jobs);
  for (size_t i = 0; i < jobs.size(); ++i) EXPECT_GE(psnrs[i], kWebgpuGrazingMinPsnrDb) << jobs[i].graph;
}

// The example graphs the runner is held to are every example graph with a WGSL form: a new
// graph in graphs/ must join one of the lists (or be refused by the wgsl target).
TEST_F(WebgpuRunner, TheListsCoverEveryExampleGraphWithAWgslForm) {
  TempDir dir("wg_webgpu_");
  std::set<std::string> listed(kWaterOnlyGraphs.begin(), kWaterOnlyGraphs.end());
  listed.insert(kScenePassGraphs.begin(), kScenePassGraphs.end());
  listed.insert(kSpectralOceanGraphs.begin(), kSpectralOceanGraphs.end());
  for (const auto& e : std::filesystem::directory_iterator(test::sourcePath("graphs"))) {
    if (e.path().extension() != ".json") continue;
    const std::string name = e.path().stem().string();
    CmdResult c = wgRun("compile " + test::shellQuote(e.path().string()) + " -o " + test::shellQuote(dir / name) +
                        " --target wgsl --quiet");
    if (c.exit != 0) {
      EXPECT_NE(c.err.find("[WG045]"), std::string::npos) << name << ": " << c.err;
      EXPECT_EQ(listed.count(name), 0u) << name;
      continue;
    }
    EXPECT_EQ(listed.count(name), 1u) << name << " has a WGSL form but is in neither list";
    nlohmann::json manifest = nlohmann::json::parse(test::readFile(dir / (name + "/" + name + ".manifest.json")));
    EXPECT_EQ(manifest.contains("oceans"), std::count(kSpectralOceanGraphs.begin(), kSpectralOceanGraphs.end(), name) == 1)
        << name;
    if (manifest.contains("oceans")) continue;
    const bool waterOnly = manifest["passes"] == nlohmann::json::array({"water_surface"});
    EXPECT_EQ(waterOnly, std::count(kWaterOnlyGraphs.begin(), kWaterOnlyGraphs.end(), name) == 1) << name;
  }
}

// The scene passes at half the frame's size (every node's `resolution` 0.5, so the manifest
// lists "pass_scales"): the runner sizes its targets from the plan as the runtime does and
// shrinks the scene colour by a filtered pass as the runtime's GL_LINEAR blit. deferred_underwater:
// depth, colour copy and the G-buffer halved (measured 38.1 dB); classic_webgl: depth,
// reflection and refraction (39.7 dB). In the built-in scene: its bar.
TEST_F(WebgpuRunner, HalfResolutionScenePassesMatchGlsl330) {
  TempDir dir("wg_webgpu_half_");
  std::vector<RunnerJob> jobs;
  for (const char* g : {"deferred_underwater", "classic_webgl"}) {
    int scaled = 0;
    nlohmann::json graph = halfResolutionGraph(g, &scaled);
    ASSERT_GT(scaled, 0) << g;
    test::writeFile(dir / (std::string(g) + ".json"), graph.dump(2));
    jobs.push_back({dir / (std::string(g) + ".json"), "above", true});
  }
  std::vector<double> psnrs = comparedPsnrs(jobs);
  for (size_t i = 0; i < jobs.size(); ++i) EXPECT_GE(psnrs[i], kWebgpuBuiltinSceneMinPsnrDb) << jobs[i].graph;
}

// The runtime's shaders as the runner takes them, without a browser
// (clients/webgpu/test/scene_shaders.test.mjs under node --test): every one the passes use
// translated by naga and valid, the uniform block's offsets the runner fills, the clip-space
// conversion on the vertex stages only, and a SceneShaderError naming what it cannot take (a
// missing shader, a G-buffer input with no location, a non-ES source, a uniform type with no
// layout, a shader naga refuses). Needs Node.js and the npm packages, not Chromium.
TEST(WebgpuSceneShaders, ChecksPassUnderNode) {
  if (!haveTool("node")) GTEST_SKIP() << "Node.js (node) is not on PATH";
  const std::string client = test::sourcePath("clients/webgpu");
  CmdResult n = sh(test::shellQuote(test::sourcePath("clients/three/test/npm_ci_cached.sh")) + " " + test::shellQuote(client));
  ASSERT_EQ(n.exit, 0) << "installing clients/webgpu's npm packages failed: " << n.err;
  TempDir dir("wg_webgpu_");
  CmdResult d = wgRun("scene -o " + test::shellQuote(dir / "scene.json"));
  ASSERT_EQ(d.exit, 0) << d.err;
  CmdResult t = sh("cd " + test::shellQuote(client) + " && WG_SCENE_DESCRIPTION=" + test::shellQuote(dir / "scene.json") +
                   " timeout 50 node --test test/scene_shaders.test.mjs");
  EXPECT_EQ(t.exit, 0) << t.out << t.err;
  EXPECT_NE(t.out.find("# pass 7"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("# fail 0"), std::string::npos) << t.out;
}

// The ocean simulation's plumbing without a browser (clients/webgpu/test/ocean.test.mjs under
// node --test), against a device that records what it is asked for: the pass order of a
// filtered and an unfiltered cascade, the slope and moments maps made with log2 N + 1 mip
// levels, the pack drawing level 0 of three maps, each downsample sampling a view of level
// l - 1 alone and drawing views of level l, the manifest's "filtered" (not its texture list)
// deciding which cascades are filtered. Needs Node.js, not Chromium or the npm packages.
TEST(WebgpuOcean, PlumbingChecksPassUnderNode) {
  if (!haveTool("node")) GTEST_SKIP() << "Node.js (node) is not on PATH";
  CmdResult t = sh("cd " + test::shellQuote(test::sourcePath("clients/webgpu")) + " && timeout 50 node --test test/ocean.test.mjs");
  EXPECT_EQ(t.exit, 0) << t.out << t.err;
  EXPECT_NE(t.out.find("# pass 4"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("# fail 0"), std::string::npos) << t.out;
}
#endif

}  // namespace
}  // namespace wg::eco
