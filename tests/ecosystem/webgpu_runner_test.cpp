// GRAPH.wgsl executed: clients/webgpu's runner draws the water in headless Chromium's WebGPU
// (SwiftShader) and the frame is compared with the GL runtime's glsl330 render of the same
// camera, the water alone over black through clamp and the sRGB encoding
// (`render --scene none --tonemap none --exposure 0`). The runner renders no scene, so it
// runs the graphs whose manifest lists the water_surface pass alone, from two cameras; a
// graph needing scene passes is refused by name. Skipped (with the reason) without Node.js,
// Chromium or the GL runtime; never passed for want of them.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "eco_support.h"
#ifdef WG_HAVE_RUNTIME
#include "runtime/image.h"
#endif

namespace wg::eco {
namespace {

#ifdef WG_HAVE_RUNTIME
// As the vk450 and three.js comparisons: a float path and another rasteriser agree to 40 dB.
constexpr double kWebgpuMinPsnrDb = 40.0;
constexpr const char* kRunnerSize = "320x180";

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
    // The runner takes uniform values and the grid from the three.js client, and playwright-core from its own.
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

  static CmdResult runWebgpu(const TempDir& dir, const std::string& base, const std::string& camera, const std::string& png) {
    return sh("timeout 90 node " + test::shellQuote(test::sourcePath("clients/webgpu/test/render_webgpu.mjs")) +
              " --dir " + test::shellQuote(dir.path()) + " --manifest " + base + ".manifest.json --description " +
              test::shellQuote(dir / "scene.json") + " --size " + kRunnerSize + " --camera " + camera +
              " --time 3.5 --grid 128 --png " + test::shellQuote(png));
  }

  // Compiles `graphRel` for es300 (the three.js client reads its manifest's uniforms) and wgsl.
  static void compileInto(const TempDir& dir, const std::string& graph) {
    CmdResult c = wgRun("compile " + test::shellQuote(graph) + " -o " + test::shellQuote(dir.path()) +
                        " --target es300,wgsl --textures --quiet");
    ASSERT_EQ(c.exit, 0) << c.err;
    CmdResult s = wgRun("scene -o " + test::shellQuote(dir / "scene.json"));
    ASSERT_EQ(s.exit, 0) << s.err;
  }

  // PSNR in dB of the WebGPU frame against the glsl330 render.
  static double comparedPsnr(const std::string& graphRel, const std::string& camera) {
    TempDir dir("wg_webgpu_");
    const std::string graph = test::sourcePath(graphRel);
    const std::string base = std::filesystem::path(graph).stem().string();
    compileInto(dir, graph);
    const std::string reference = dir / "glsl330.png", webgpu = dir / "webgpu.png";
    CmdResult r = wgRun("render " + test::shellQuote(graph) + " -o " + test::shellQuote(reference) + " --target glsl330 " +
                        "--scene none --tonemap none --exposure 0 --size " + kRunnerSize + " --camera " + camera +
                        " --time 3.5 --grid 128");
    EXPECT_EQ(r.exit, 0) << r.err;
    CmdResult w = runWebgpu(dir, base, camera, webgpu);
    EXPECT_EQ(w.exit, 0) << w.out << w.err;
    if (r.exit || w.exit) return 0;
    rt::Image a = rt::readPng(reference), b = rt::readPng(webgpu);
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    if (a.width != b.width || a.height != b.height) return 0;
    double psnr = rt::psnrRgb8(a, b);
    std::printf("WebGPU (wgsl) vs runtime (glsl330), %s camera %s %s: PSNR %.2f dB\n", graphRel.c_str(), camera.c_str(),
                kRunnerSize, psnr);
    return psnr;
  }

  static inline std::string skip_, npmError_;
};

// Every example graph the runner can draw (water_surface alone): the lake (Fresnel, sRGB
// parameters), the lagoon (its own PNG through texture_sample, time, sun), the shelf, and
// topdown (Gerstner waves in the vertex stage, twelve time phases). From above and from the
// top-down camera, at the bar of 40 dB.
TEST_F(WebgpuRunner, WaterOnlyExampleGraphsMatchGlsl330) {
  for (const char* graph : {"graphs/lake.json", "graphs/lagoon.json", "graphs/shelf.json", "graphs/topdown.json"})
    for (const char* camera : {"above", "topdown"}) EXPECT_GE(comparedPsnr(graph, camera), kWebgpuMinPsnrDb) << graph << " " << camera;
}

// From the grazing camera the two rasterisers differ where nothing about the shader does:
// on the horizon row, where the grid's far edge runs along pixel centres (SwiftShader and
// llvmpipe break those ties differently: the lake measures 45.2 dB above and 39.98 dB here,
// all of the difference in 11 pixels of one row), and where the lagoon's texture is minified
// far without mipmaps (aliasing: 52.2 dB without the 244 pixels of rows 90-97, 37.1 dB with
// them). The bar is the three.js client's for the same view (tests/ecosystem/three_client_test.cpp).
constexpr double kWebgpuGrazingMinPsnrDb = 37.0;
TEST_F(WebgpuRunner, WaterOnlyExampleGraphsMatchGlsl330AtGrazing) {
  for (const char* graph : {"graphs/lake.json", "graphs/lagoon.json", "graphs/shelf.json", "graphs/topdown.json"})
    EXPECT_GE(comparedPsnr(graph, "grazing"), kWebgpuGrazingMinPsnrDb) << graph;
}

TEST_F(WebgpuRunner, AGraphNeedingScenePassesIsRefusedByName) {
  TempDir dir("wg_webgpu_");
  compileInto(dir, test::sourcePath("graphs/pool.json"));
  CmdResult w = runWebgpu(dir, "pool", "above", dir / "webgpu.png");
  EXPECT_EQ(w.exit, 1) << w.out << w.err;
  EXPECT_NE(w.err.find("graph 'pool' needs passes this runner does not render: depth_prepass, scene_color_copy, "
                       "environment_cubemap"),
            std::string::npos)
      << w.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "webgpu.png"));
}
#endif

}  // namespace
}  // namespace wg::eco
