// The three.js client (clients/three/): a graph's es300 output rendered by three.js in
// headless Chromium (Debian's, driven by playwright-core from npm) must match
// `watergraph render --target es300` of the same graph, camera, size and time — the same
// shaders on the runtime's OpenGL ES (Mesa llvmpipe): the water alone (`--scene none`),
// and every example graph with the passes its manifest lists in the built-in scene, which
// the client builds from `watergraph scene`. Both sides render linear radiance into
// RGBA16F targets and show it through the same output transform (the description's
// shader), so the colour pipeline is checked too: 128 sRGB in, 128 out; linear 0.5 out as
// 188; values above 1 kept until the exposure. Thresholds and the measured PSNR are in
// docs/ecosystem.md. npm and Chromium missing is a failure, not a
// skip: CI provides both (scripts/setup.sh installs chromium).
#ifdef WG_HAVE_RUNTIME
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <tuple>

#include <nlohmann/json.hpp>

#include "eco_support.h"
#include "codegen/compile.h"
#include "codegen/water_surface_eval.h"
#include "core/graph_io.h"
#include "core/view_transform.h"
#include "nodes/registry.h"
#include "nodes/texture_source.h"
#include "runtime/floating_buoys.h"
#include "runtime/image.h"
#include "runtime/scene.h"

namespace wg::eco {
namespace {

// Both renderers rasterise the same triangles with the same shaders; what differs is
// float rounding on two software GPUs (llvmpipe, SwiftShader), which pixels exactly on the
// grid's far edge each covers, and, where a texture is minified without mipmaps, which
// texel a far pixel lands on. Thresholds sit about 3.5 dB under the measured figures
// (through the output transform, on both sides); a wrong camera or time costs far more
// (docs/ecosystem.md has the figures).
constexpr double kLakeMinPsnrDb = 40.0;           // measured 43.7
constexpr double kTexturedWavesMinPsnrDb = 37.0;  // measured 41.5
// Every example graph in the built-in scene, every pass its manifest lists: the same
// shaders and scene on both sides, so what differs is float rounding on two software GPUs
// (magnified where a reflection or refraction ray grazes an edge, or a depth
// linearisation divides by a small difference) and pixels on triangle edges. The issue's
// floor (issue 38: "three.js matches the runtime >= 33 dB"); the figures measured, 36.9 dB
// and up, are in docs/ecosystem.md.
constexpr double kBuiltinSceneMinPsnrDb = 33.0;
constexpr const char* kSceneSize = "192x108";

constexpr const char* kSize = "320x180";
constexpr const char* kTime = "3.5";
constexpr int kGrid = 128;

std::string clientDir() { return test::sourcePath("clients/three"); }

std::string csv(const glm::vec3& v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.9g,%.9g,%.9g", v.x, v.y, v.z);
  return buf;
}

std::string num(float f) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", f);
  return buf;
}

// One job of render_graph.mjs's batch: the graph compiled into `out` drawn by the client
// from `cam` at `size`, in the built-in scene or (builtin false) alone over black as
// `render --scene none`, written to `screenshot`.
nlohmann::json sceneJob(const std::string& out, const std::string& manifest, const rt::Camera& cam,
                        const std::string& screenshot, const std::string& size, bool builtin) {
  return {{"dir", out}, {"manifest", manifest}, {"size", size},
          {"eye", csv(cam.position)}, {"target", csv(cam.target)}, {"up", csv(cam.up())},
          {"fov", num(cam.fovYDegrees)}, {"near", num(cam.nearPlane)}, {"far", num(cam.farPlane)},
          {"time", kTime}, {"grid", std::to_string(kGrid)}, {"screenshot", screenshot}, {"builtin", builtin}};
}

nlohmann::json builtinSceneJob(const std::string& out, const std::string& manifest, const rt::Camera& cam,
                               const std::string& screenshot) {
  return sceneJob(out, manifest, cam, screenshot, kSceneSize, true);
}

// Runs the client over a batch of jobs (written to dir/jobs.json) in one browser.
CmdResult renderBatch(const std::string& dir, const nlohmann::json& batch, const std::string& description,
                      int seconds) {
  const std::string batchFile = dir + "/jobs.json";
  std::ofstream(batchFile) << batch.dump(1);
  return sh("timeout " + std::to_string(seconds) + " node " + test::shellQuote(clientDir() + "/test/render_graph.mjs") +
            " --batch " + test::shellQuote(batchFile) + " --description " + test::shellQuote(description));
}

class ThreeClient : public ::testing::Test {
 protected:
  // npm ci once per lock file (cached in clients/three/node_modules); Chromium must exist.
  static void SetUpTestSuite() {
    CmdResult r = sh(test::shellQuote(clientDir() + "/test/npm_ci_cached.sh"));
    npmError_ = r.exit == 0 ? "" : "installing the client's npm packages failed: " + r.err;
    if (npmError_.empty() && !std::filesystem::exists("/usr/bin/chromium"))
      npmError_ = "Debian's chromium is not installed (/usr/bin/chromium): run scripts/setup.sh";
  }
  void SetUp() override { ASSERT_TRUE(npmError_.empty()) << npmError_; }

  // Renders `graph` (compiled into `dir`) with three.js; returns the node driver's result.
  // With `description` (a `watergraph scene` file) the client runs its passes over an
  // empty scene, the output transform last, as `render --scene none`; without one it draws
  // only the water.
  CmdResult renderInChromium(const TempDir& dir, const std::string& graphBase, const std::string& camera,
                             const std::string& png, const std::string& description = "") {
    auto cam = rt::cameraPreset(camera);
    EXPECT_TRUE(cam.has_value());
    std::string cmd = "timeout 50 node " + test::shellQuote(clientDir() + "/test/render_graph.mjs") +
                      " --dir " + test::shellQuote(dir.path()) + " --manifest " + graphBase + ".manifest.json" +
                      " --size " + kSize + " --eye=" + csv(cam->position) + " --target=" + csv(cam->target) +
                      " --up=" + csv(cam->up()) + " --fov " + num(cam->fovYDegrees) + " --near " +
                      num(cam->nearPlane) + " --far " + num(cam->farPlane) + " --time " + kTime + " --grid " +
                      std::to_string(kGrid) + " --screenshot " + test::shellQuote(png) +
                      (description.empty() ? "" : " --description " + test::shellQuote(description));
    return sh(cmd);
  }

  // Compiles and renders `graph` both ways; returns the PSNR in dB.
  double comparedPsnr(const std::string& graphRel, const std::string& camera) {
    TempDir dir("wg_three_");
    std::string graph = test::sourcePath(graphRel);
    std::string base = std::filesystem::path(graph).stem().string();
    CmdResult c = wgRun("compile " + test::shellQuote(graph) + " -o " + test::shellQuote(dir.path()) +
                        " --target es300 --textures --quiet");
    EXPECT_EQ(c.exit, 0) << c.err;
    std::string reference = dir / "runtime.png", three = dir / "three.png";
    CmdResult r = wgRun("render " + test::shellQuote(graph) + " -o " + test::shellQuote(reference) +
                        " --target es300 --scene none --size " + kSize + " --camera " + camera + " --time " + kTime +
                        " --grid " + std::to_string(kGrid));
    EXPECT_EQ(r.exit, 0) << r.err;
    CmdResult d = wgRun("scene -o " + test::shellQuote(dir / "scene.json"));
    EXPECT_EQ(d.exit, 0) << d.err;
    CmdResult t = renderInChromium(dir, base, camera, three, dir / "scene.json");
    EXPECT_EQ(t.exit, 0) << t.out << t.err;
    if (c.exit || r.exit || d.exit || t.exit) return 0;
    rt::Image a = rt::readPng(reference), b = rt::readPng(three);
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    if (a.width != b.width || a.height != b.height) return 0;
    double psnr = rt::psnrRgb8(a, b);
    std::printf("three.js vs runtime, %s camera %s %s t=%s: PSNR %.2f dB\n", graphRel.c_str(), camera.c_str(), kSize,
                kTime, psnr);
    return psnr;
  }

  static std::string npmError_;
};
std::string ThreeClient::npmError_;

// The candidate graph: parameters, Fresnel from the camera, no textures or time.
TEST_F(ThreeClient, LakeMatchesTheRuntime) {
  EXPECT_GE(comparedPsnr("graphs/lake.json", "above"), kLakeMinPsnrDb);
}

// Gerstner waves in the vertex stage (time_phase uniforms computed in JS), a built-in
// texture exported by `compile --textures`, u_time: from a grazing camera.
TEST_F(ThreeClient, TexturedWavesMatchTheRuntime) {
  EXPECT_GE(comparedPsnr("tests/ecosystem/data/textured_waves.json", "grazing"), kTexturedWavesMinPsnrDb);
}

// A user's PNG through texture_sample (repeat, bilinear, linear data: the manifest's
// sampler state set on the three.js texture), expressions, u_time and the sun direction:
// the lagoon example (measured 42.5 dB).
TEST_F(ThreeClient, TheLagoonsOwnTextureMatchesTheRuntime) {
  EXPECT_GE(comparedPsnr("graphs/lagoon.json", "above"), kTexturedWavesMinPsnrDb);
}

// A hand-written GLSL function (a glsl_function node) used twice through a subgraph: the
// es300 shader carries the file renamed into each node's namespace, which three.js
// compiles like any generated code.
TEST_F(ThreeClient, TheCausticPoolsOwnFunctionMatchesTheRuntime) {
  EXPECT_GE(comparedPsnr("graphs/caustic_pool.json", "above"), kTexturedWavesMinPsnrDb);
}

// Without a scene description, a graph needing passes the client then does not render
// fails in the page with one clear message naming them, instead of drawing something wrong.
TEST_F(ThreeClient, UnsupportedPassesAreAClearError) {
  TempDir dir("wg_three_");
  CmdResult c = wgRun("compile " + test::shellQuote(test::sourcePath("graphs/deferred_underwater.json")) + " -o " +
                      test::shellQuote(dir.path()) + " --target es300 --textures --quiet");
  ASSERT_EQ(c.exit, 0) << c.err;
  CmdResult t = renderInChromium(dir, "deferred_underwater", "above", dir / "three.png");
  EXPECT_EQ(t.exit, 1) << t.out << t.err;
  EXPECT_NE(t.err.find("WaterGraphError: graph 'deferred_underwater' needs render passes the three.js client does not "
                       "provide: "),
            std::string::npos)
      << t.err;
  EXPECT_NE(t.err.find("depth_prepass (resource scene_depth: pass it in options.resources)"), std::string::npos)
      << t.err;
  EXPECT_NE(t.err.find("deferred_water (resource underwater: deferred water needs the client's passes: give a scene "
                       "description)"),
            std::string::npos)
      << t.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "three.png"));
}

// A spectral ocean's simulation passes run the runtime's shaders, which come with a scene
// description: without one it is one clear message naming the pass, and no frame.
TEST_F(ThreeClient, ASpectralOceanWithoutADescriptionIsAClearError) {
  TempDir dir("wg_three_");
  CmdResult c = wgRun("compile " + test::shellQuote(test::sourcePath("graphs/open_ocean.json")) + " -o " +
                      test::shellQuote(dir.path()) + " --target es300 --textures --quiet");
  ASSERT_EQ(c.exit, 0) << c.err;
  CmdResult t = renderInChromium(dir, "open_ocean", "above", dir / "three.png");
  EXPECT_EQ(t.exit, 1) << t.out << t.err;
  EXPECT_NE(t.err.find("WaterGraphError: graph 'open_ocean' needs render passes the three.js client does not provide: "
                       "ocean_simulation (a spectral ocean: its passes' shaders come with a scene description)"),
            std::string::npos)
      << t.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "three.png"));
}

// Every example graph (graphs/*.json) at two cameras, in the built-in scene with every pass
// its manifest lists, rendered by the client (one browser for all) and by the runtime.
TEST_F(ThreeClient, EveryExampleGraphMatchesTheRuntimeInTheBuiltInScene) {
  TempDir dir("wg_three_");
  const std::string description = dir / "scene.json";
  CmdResult s = wgRun("scene -o " + test::shellQuote(description));
  ASSERT_EQ(s.exit, 0) << s.err;
  std::vector<std::string> graphs;
  for (const auto& e : std::filesystem::directory_iterator(test::sourcePath("graphs")))
    if (e.path().extension() == ".json") graphs.push_back(e.path().stem().string());
  std::sort(graphs.begin(), graphs.end());
  ASSERT_GE(graphs.size(), 10u);
  struct Job {
    std::string graph, camera, reference, three;
  };
  std::vector<Job> jobs;
  nlohmann::json batch = nlohmann::json::array();
  for (const auto& g : graphs) {
    const std::string graph = test::sourcePath("graphs/" + g + ".json"), out = dir / g;
    // The spectral ocean under this sun: ThreeClient.TheSpectralOceanMatchesTheRuntimeFromTwoCameras.
    if (g == "open_ocean") continue;
    CmdResult c = wgRun("compile " + test::shellQuote(graph) + " -o " + test::shellQuote(out) +
                        " --target es300 --textures --quiet");
    ASSERT_EQ(c.exit, 0) << g << ": " << c.err;
    for (const char* camera : {"above", "grazing"}) {
      Job job{g, camera, dir / (g + "." + camera + ".runtime.png"), dir / (g + "." + camera + ".three.png")};
      CmdResult r = wgRun("render " + test::shellQuote(graph) + " -o " + test::shellQuote(job.reference) +
                          " --target es300 --size " + kSceneSize + " --camera " + camera + " --time " + kTime);
      ASSERT_EQ(r.exit, 0) << g << ": " << r.err;
      auto cam = rt::cameraPreset(camera);
      batch.push_back(builtinSceneJob(out, g + ".manifest.json", *cam, job.three));
      jobs.push_back(job);
    }
  }
  CmdResult t = renderBatch(dir.path(), batch, description, 300);
  ASSERT_EQ(t.exit, 0) << t.out << t.err;
  for (const Job& job : jobs) {
    rt::Image a = rt::readPng(job.reference), b = rt::readPng(job.three);
    ASSERT_EQ(a.width, b.width) << job.graph;
    ASSERT_EQ(a.height, b.height) << job.graph;
    double psnr = rt::psnrRgb8(a, b);
    std::printf("three.js vs runtime, built-in scene, %s camera %s %s t=%s: PSNR %.2f dB\n", job.graph.c_str(),
                job.camera.c_str(), kSceneSize, kTime, psnr);
    EXPECT_GE(psnr, kBuiltinSceneMinPsnrDb) << job.graph << " camera " << job.camera;
  }
}

// The spectral ocean (graphs/open_ocean.json): its simulation passes run by the client
// (clients/three/watergraph-ocean.js: the runtime's pass shaders from the description, h0
// and the clocks from the compiler's open_ocean.ocean.js; its filtered cascades' slope and
// moments pyramids by watergraph-ocean-pyramid.js) before the environment cube and the
// water, in the built-in scene, from two cameras, under the default sun, at the issue's 33 dB.
// Measured 39.72 dB above and 43.98 dB grazing (docs/ecosystem.md). Before the ocean's
// shading was filtered the sun had to be put 5 degrees below the horizon: the point-sampled
// centimetre waves mirrored it into scattered glints that llvmpipe and SwiftShader put on
// different pixels (27.29 and 30.01 dB at this sun, 635 pixels above differing by more than
// 30 levels); read at each pixel's footprint, with the slope variance the footprint averages
// added to the roughness, the glints are as wide as the pixels they cover (65 such pixels).
TEST_F(ThreeClient, TheSpectralOceanMatchesTheRuntimeFromTwoCameras) {
  TempDir dir("wg_three_ocean_");
  const std::string description = dir / "scene.json", graph = test::sourcePath("graphs/open_ocean.json");
  CmdResult s = wgRun("scene -o " + test::shellQuote(description));
  ASSERT_EQ(s.exit, 0) << s.err;
  CmdResult c = wgRun("compile " + test::shellQuote(graph) + " -o " + test::shellQuote(dir / "out") +
                      " --target es300 --textures --quiet");
  ASSERT_EQ(c.exit, 0) << c.err;
  nlohmann::json batch = nlohmann::json::array();
  std::vector<std::string> cameras = {"above", "grazing"};
  for (const std::string& camera : cameras) {
    CmdResult r = wgRun("render " + test::shellQuote(graph) + " -o " + test::shellQuote(dir / (camera + ".runtime.png")) +
                        " --target es300 --size " + kSceneSize + " --camera " + camera + " --time " + kTime);
    ASSERT_EQ(r.exit, 0) << r.err;
    batch.push_back(builtinSceneJob(dir / "out", "open_ocean.manifest.json", *rt::cameraPreset(camera),
                                    dir / (camera + ".three.png")));
  }
  CmdResult t = renderBatch(dir.path(), batch, description, 240);
  ASSERT_EQ(t.exit, 0) << t.out << t.err;
  for (const std::string& camera : cameras) {
    rt::Image a = rt::readPng(dir / (camera + ".runtime.png")), b = rt::readPng(dir / (camera + ".three.png"));
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    double psnr = rt::psnrRgb8(a, b);
    std::printf("three.js vs runtime, built-in scene, open_ocean camera %s %s t=%s: PSNR %.2f dB\n",
                camera.c_str(), kSceneSize, kTime, psnr);
    EXPECT_GE(psnr, kBuiltinSceneMinPsnrDb) << "open_ocean camera " << camera;
  }
}

// The scene passes at half the frame's size (every node's `resolution` 0.5, so the manifest
// lists "pass_scales"): the client sizes its targets as the runtime does and shrinks the
// scene colour by a filtered blit, so both still agree. deferred_underwater: depth, colour
// copy and the G-buffer halved; classic_webgl: depth, reflection and refraction.
TEST_F(ThreeClient, HalfResolutionScenePassesMatchTheRuntime) {
  TempDir dir("wg_three_");
  const std::string description = dir / "scene.json";
  CmdResult s = wgRun("scene -o " + test::shellQuote(description));
  ASSERT_EQ(s.exit, 0) << s.err;
  struct Job {
    std::string graph, reference, three;
  };
  std::vector<Job> jobs;
  nlohmann::json batch = nlohmann::json::array();
  auto cam = rt::cameraPreset("above");
  ASSERT_TRUE(cam.has_value());
  for (const char* g : {"deferred_underwater", "classic_webgl"}) {
    int scaled = 0;
    nlohmann::json graph = halfResolutionGraph(g, &scaled);
    ASSERT_GT(scaled, 0) << g;
    const std::string file = dir / (std::string(g) + ".json"), out = dir / g;
    test::writeFile(file, graph.dump(2));
    CmdResult c = wgRun("compile " + test::shellQuote(file) + " -o " + test::shellQuote(out) + " --target es300 --textures --quiet");
    ASSERT_EQ(c.exit, 0) << g << ": " << c.err;
    nlohmann::json manifest = nlohmann::json::parse(test::readFile(out + "/" + g + ".manifest.json"));
    ASSERT_TRUE(manifest.contains("pass_scales")) << g;
    EXPECT_EQ(manifest["pass_scales"]["depth_prepass"], 0.5) << g;
    Job job{g, dir / (std::string(g) + ".runtime.png"), dir / (std::string(g) + ".three.png")};
    CmdResult r = wgRun("render " + test::shellQuote(file) + " -o " + test::shellQuote(job.reference) +
                        " --target es300 --size " + kSceneSize + " --camera above --time " + kTime);
    ASSERT_EQ(r.exit, 0) << g << ": " << r.err;
    batch.push_back(builtinSceneJob(out, std::string(g) + ".manifest.json", *cam, job.three));
    jobs.push_back(job);
  }
  CmdResult t = renderBatch(dir.path(), batch, description, 120);
  ASSERT_EQ(t.exit, 0) << t.out << t.err;
  for (const Job& job : jobs) {
    rt::Image a = rt::readPng(job.reference), b = rt::readPng(job.three);
    ASSERT_EQ(a.width, b.width) << job.graph;
    double psnr = rt::psnrRgb8(a, b);
    std::printf("three.js vs runtime, scene passes at 0.5, %s camera above %s t=%s: PSNR %.2f dB\n", job.graph.c_str(),
                kSceneSize, kTime, psnr);
    EXPECT_GE(psnr, kBuiltinSceneMinPsnrDb) << job.graph;
  }
}

// Pixels made red by adding the box: their redness (red minus the larger of green and
// blue) up by more than 80 of 255, red not lower (the water and scene around it are blue,
// grey and sand). Redness, not red alone: the daylight sky the water reflects is bright
// (its red near 1 already, ~206 of 255 where the cube's reflection falls), so the cube
// turns it red mostly by taking green and blue away.
int reddenedPixels(const rt::Image& without, const rt::Image& with) {
  int count = 0;
  auto redness = [](const rt::Image& img, size_t p) {
    return img.rgba8[p] - std::max(img.rgba8[p + 1], img.rgba8[p + 2]);
  };
  for (size_t p = 0; p + 3 < with.rgba8.size() && p + 3 < without.rgba8.size(); p += 4)
    count += with.rgba8[p] >= without.rgba8[p] && redness(with, p) - redness(without, p) > 80 ? 1 : 0;
  return count;
}

// A user's own three.js object in the scene the client's passes draw: classic_webgl
// (planar reflection and refraction, clip planes, opaque water over them) from the `above`
// camera, with an unlit red cube added to the page's scene. Above the water and above the
// camera's view (35 degrees over the view axis; the frustum ends at 27.5), the cube can turn
// the frame red only through the reflection pass; under the water, only through the
// refraction pass (its top 0.1 under the flat surface), since the opaque water is drawn
// over it. A pass that drew only the built-in scene, or clipped the user's objects on the
// wrong side, leaves no red pixel.
TEST_F(ThreeClient, AUsersOwnObjectIsReflectedAndRefracted) {
  TempDir dir("wg_three_");
  const std::string description = dir / "scene.json";
  CmdResult s = wgRun("scene -o " + test::shellQuote(description));
  ASSERT_EQ(s.exit, 0) << s.err;
  const std::string out = dir / "classic_webgl";
  CmdResult c = wgRun("compile " + test::shellQuote(test::sourcePath("graphs/classic_webgl.json")) + " -o " +
                      test::shellQuote(out) + " --target es300 --textures --quiet");
  ASSERT_EQ(c.exit, 0) << c.err;
  auto cam = rt::cameraPreset("above");
  ASSERT_TRUE(cam.has_value());
  // Each cube against the same view without it, with no tone curve (the count is of the
  // cube's red, not of a curve's shoulder): the reflected one at -1 EV, where the bright
  // sky it lies on does not clip to white, the refracted one at 0 EV, where it stands out
  // through the absorbing water.
  struct Job {
    const char* name;
    const char* box;  // x,y,z,edge; "" for none
    double exposure;
  };
  const Job jobs[] = {{"none_dark", "", -1.0},
                      {"above_water", "-4.7,14,4.6,3", -1.0},
                      {"none", "", 0.0},
                      {"under_water", "8,-0.5,-6,0.8", 0.0}};
  nlohmann::json batch = nlohmann::json::array();
  for (const Job& job : jobs) {
    nlohmann::json j = builtinSceneJob(out, "classic_webgl.manifest.json", *cam, dir / (std::string(job.name) + ".png"));
    if (*job.box) j["box"] = job.box;
    j["tonemap"] = "none";
    j["exposure"] = job.exposure;
    batch.push_back(j);
  }
  CmdResult t = renderBatch(dir.path(), batch, description, 120);
  ASSERT_EQ(t.exit, 0) << t.out << t.err;
  int reflected = reddenedPixels(rt::readPng(dir / "none_dark.png"), rt::readPng(dir / "above_water.png"));
  int refracted = reddenedPixels(rt::readPng(dir / "none.png"), rt::readPng(dir / "under_water.png"));
  std::printf("red cube over the water: %d pixels reddened (reflection); under the water: %d (refraction), of %s\n",
              reflected, refracted, kSceneSize);
  EXPECT_GE(reflected, 20);
  EXPECT_GE(refracted, 20);
}

// The gallery (clients/three/example/) as a person opens it: every example graph compiled
// with its presets, the page loaded, frames drawn, two graphs picked in turn (deferred
// water among them), a tone mapper picked and the exposure slider moved, and no console
// error or failed request. The buoys float on the last graph (topdown's Gerstner waves)
// by its surface query, where the runtime floats them at the page's time: the positions
// within 1e-9 m (the query agrees with the vertex stage in double), the up axes within the
// runtime's central differences' 1e-3.
TEST_F(ThreeClient, TheGalleryLoadsAndSwitchesGraphsWithoutAConsoleError) {
  TempDir dir("wg_gallery_buoys_");
  CmdResult t = sh("cd " + test::shellQuote(clientDir()) + " && timeout 200 node test/gallery_check.mjs --watergraph " +
                   test::shellQuote(test::watergraphBinary()) +
                   " --size 480x270 --switch deferred_underwater,topdown --tonemap agx --exposure 0.5 --buoys-json " +
                   test::shellQuote(dir / "buoys.json"));
  EXPECT_EQ(t.exit, 0) << t.out << t.err;
  EXPECT_NE(t.out.find("switched to deferred_underwater, topdown: no console errors"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("view agx at 0.5 EV, frame rgba16f"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("3 buoys floating on topdown"), std::string::npos) << t.out;
  if (t.exit != 0) return;
  const nlohmann::json floating = nlohmann::json::parse(test::readFile(dir / "buoys.json"));
  const double time = floating["time"].get<double>();
  Diagnostics diags;
  auto graph = loadGraphFile(test::sourcePath("graphs/topdown.json"), diags);
  ASSERT_TRUE(graph);
  auto program = buildProgram(*graph, defaultRegistry(), diags);
  ASSERT_TRUE(program);
  std::vector<Value> parameters;
  for (const auto& p : program->parameters) parameters.push_back(p.defaultValue);
  const std::vector<rt::FloatingPose> runtime = rt::floatingBuoys(*program, parameters, time);
  ASSERT_EQ(floating["buoys"].size(), runtime.size());
  for (size_t i = 0; i < runtime.size(); ++i) {
    const auto& b = floating["buoys"][i];
    const glm::dvec2 rest = rt::buoyRestPoints()[i];
    const WaterSurfacePoint s = waterSurfaceAt(*program, parameters, rest.x, rest.y, time);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(b["position"][k].get<double>(), s.position[k], 1e-9) << "buoy " << i;
      EXPECT_NEAR(b["normal"][k].get<double>(), runtime[i].up[k], 1e-3) << "buoy " << i;
    }
  }
}

// `watergraph scene` writes the same description to a file as to stdout, and refuses a sun
// below the horizon's range as a usage error.
TEST(SceneCommand, WritesTheDescriptionToAFileOrStdout) {
  TempDir dir("wg_three_");
  CmdResult toFile = wgRun("scene -o " + test::shellQuote(dir / "scene.json") + " --sun-elevation 12");
  ASSERT_EQ(toFile.exit, 0) << toFile.err;
  CmdResult toStdout = wgRun("scene --sun-elevation 12");
  ASSERT_EQ(toStdout.exit, 0) << toStdout.err;
  std::ifstream in(dir / "scene.json");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, toStdout.out);
  EXPECT_EQ(nlohmann::json::parse(text)["format"], std::string("watergraph-scene-2"));
  CmdResult bad = wgRun("scene --sun-elevation 100");
  EXPECT_EQ(bad.exit, 2) << bad.out;
  CmdResult nan = wgRun("scene --sun-azimuth nan");  // would write a NaN sun as JSON null
  EXPECT_EQ(nan.exit, 2) << nan.out;
  EXPECT_NE(nan.err.find("must be a finite number"), std::string::npos) << nan.err;
}

// The bottom-centre pixel of a render from the `above` camera: water.
const uint8_t* waterPixel(const rt::Image& img) {
  return &img.rgba8[(static_cast<size_t>(img.height) * 7 / 8 * img.width + img.width / 2) * 4];
}

// 255 times the output transform of a grey `linear` through `view`, rounded: what an 8-bit
// display value must be (core/view_transform.h, the reference of every runtime).
int displayed(double linear, ToneMapper mapper, double ev) {
  return static_cast<int>(std::lround(255 * outputTransform({mapper, ev}, {linear, linear, linear})[1]));
}

// The colour pipeline in the client, as tests/runtime/color_pipeline_test.cpp checks the
// runtime's: graphs showing one grey on the water, alone over black (64x36, the `above`
// camera), read at a water pixel.
//   a 4x4 PNG of 128 through texture_sample (color_space srgb): 128 (+-1);
//   a linear 0.5 parameter: 188 with the default view (none, 0 EV), also where the host
//     made its renderer with three.js's own HDR output (a half-float output buffer, ACES,
//     sRGB), which the output pass sets aside (through three.js's it would be 174);
//   a linear 4 at -2 EV: 255 and at -3 EV: 188, so the frame holds radiance above 1 until
//     the exposure (a frame clamped to 1 would give 137 and 99);
//   aces, agx and neutral at -1 EV on 4: the reference (+-1);
//   with the half-float extensions hidden from the page: the frame RGBA8, said once as a
//     warning, and 4 at -3 EV is 99: clipped, as the warning says;
//   an unknown tone mapper: that page fails with a WaterGraphError naming the option.
TEST_F(ThreeClient, TheColourPipelineMatchesTheRuntimesContract) {
  TempDir dir("wg_three_");
  rt::Image png;
  png.width = png.height = 4;
  png.rgba8.assign(4 * 4 * 4, 128);
  for (size_t i = 3; i < png.rgba8.size(); i += 4) png.rgba8[i] = 255;
  rt::writePng(dir / "grey.png", png);
  const std::string out = dir / "out";
  for (const auto& [name, color, half] : {std::tuple{"tex", "t.rgb", "0.5"}, std::tuple{"half", "$half", "0.5"},
                                          std::tuple{"four", "$half", "4"}}) {
    test::writeFile(dir / (std::string(name) + ".json"),
                    std::string(R"({"version": 1, "name": "grey",
      "parameters": {"half": {"type": "vec3", "default": [)") + half + ", " + half + ", " + half +
                        R"(], "description": "data, not a colour"}},
      "nodes": [{"id": "t", "type": "texture_sample", "options": {"texture": "grey.png", "color_space": "srgb"}}],
      "outputs": {"fragment": {"color": ")" + color + R"("}}})");
    CmdResult c = wgRun("compile " + test::shellQuote(dir / (std::string(name) + ".json")) + " -o " +
                        test::shellQuote(out) + " --target es300 --textures --quiet");
    ASSERT_EQ(c.exit, 0) << name << ": " << c.err;
  }
  const std::string description = dir / "scene.json";
  ASSERT_EQ(wgRun("scene -o " + test::shellQuote(description)).exit, 0);
  auto cam = rt::cameraPreset("above");
  ASSERT_TRUE(cam.has_value());
  struct Job {
    const char* graph;
    const char* tonemap;  // "" for the manifest's view
    double exposure;      // NaN for the manifest's view
    bool noFloat;
    int expected;
    int tolerance;
    bool hostToneMapping = false;
  };
  const double manifestsView = std::nan("");
  const Job jobs[] = {
      {"tex", "", manifestsView, false, 128, 1},
      {"half", "", manifestsView, false, 188, 0},
      {"half", "", manifestsView, false, 188, 0, /*hostToneMapping=*/true},
      {"four", "none", -2, false, 255, 0},
      {"four", "none", -3, false, 188, 0},
      {"four", "aces", -1, false, displayed(4, ToneMapper::Aces, -1), 1},
      {"four", "agx", -1, false, displayed(4, ToneMapper::Agx, -1), 1},
      {"four", "neutral", -1, false, displayed(4, ToneMapper::Neutral, -1), 1},
      {"four", "none", -3, true, displayed(1, ToneMapper::None, -3), 0},
  };
  EXPECT_EQ(displayed(0.5, ToneMapper::None, 0), 188);
  EXPECT_EQ(displayed(1, ToneMapper::None, -3), 99);
  nlohmann::json batch = nlohmann::json::array();
  for (size_t i = 0; i < std::size(jobs); ++i) {
    nlohmann::json j = sceneJob(out, std::string(jobs[i].graph) + ".manifest.json", *cam,
                                dir / ("job" + std::to_string(i) + ".png"), "64x36", false);
    if (*jobs[i].tonemap) j["tonemap"] = jobs[i].tonemap;
    if (!std::isnan(jobs[i].exposure)) j["exposure"] = num(static_cast<float>(jobs[i].exposure));
    if (jobs[i].noFloat) j["nofloat"] = true;
    if (jobs[i].hostToneMapping) j["host-tone-mapping"] = true;
    batch.push_back(j);
  }
  nlohmann::json bad = sceneJob(out, "half.manifest.json", *cam, dir / "bad.png", "64x36", false);
  bad["tonemap"] = "filmic";
  batch.push_back(bad);
  CmdResult t = renderBatch(dir.path(), batch, description, 120);
  EXPECT_EQ(t.exit, 1) << t.out << t.err;  // the bad job only
  EXPECT_NE(t.err.find("WaterGraphError: the render option toneMapping must be one of none, aces, agx, neutral "
                       "(got 'filmic')"),
            std::string::npos)
      << t.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.png"));
  for (size_t i = 0; i < std::size(jobs); ++i) {
    const std::string file = dir / ("job" + std::to_string(i) + ".png");
    ASSERT_TRUE(std::filesystem::exists(file)) << "job " << i << "\n" << t.out << t.err;
    rt::Image img = rt::readPng(file);
    const uint8_t* px = waterPixel(img);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(px[c], jobs[i].expected, jobs[i].tolerance)
          << jobs[i].graph << " " << jobs[i].tonemap << " at " << jobs[i].exposure << " EV"
          << (jobs[i].noFloat ? " without half floats" : "")
          << (jobs[i].hostToneMapping ? " with the host's tone mapping" : "") << ", channel " << c;
  }
  // Every frame but the one without the extensions is RGBA16F; that one says why, once.
  auto count = [&](const std::string& what) {
    size_t n = 0;
    for (size_t at = t.out.find(what); at != std::string::npos; at = t.out.find(what, at + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count(", frame rgba16f -> "), std::size(jobs) - 1) << t.out;
  EXPECT_EQ(count(", frame rgba8 -> "), 1u) << t.out;
  EXPECT_EQ(count("warning: watergraph: this WebGL 2 context has neither EXT_color_buffer_float nor "
                  "EXT_color_buffer_half_float"),
            1u)
      << t.out;
}

// The API without a browser (clients/three/test/api.test.mjs and color.test.mjs under
// node --test): the resources option, update(), time phases, the grid, the sampler state of
// node textures, the pass plan from the scene description and the passes' textures bound;
// the manifest's view and the render options, the output pass built from the
// description's shader, the RGBA8 fallback said once.
TEST_F(ThreeClient, ApiChecksPassUnderNode) {
  TempDir dir("wg_three_");
  CmdResult c = wgRun("compile " + test::shellQuote(test::sourcePath("tests/ecosystem/data/three_environment.json")) +
                      " -o " + test::shellQuote(dir.path()) + " --target es300 --quiet");
  ASSERT_EQ(c.exit, 0) << c.err;
  CmdResult d = wgRun("scene -o " + test::shellQuote(dir / "scene.json"));
  ASSERT_EQ(d.exit, 0) << d.err;
  CmdResult t = sh("cd " + test::shellQuote(clientDir()) + " && WG_THREE_FIXTURES=" + test::shellQuote(dir.path()) +
                   " timeout 50 node --test test/api.test.mjs test/color.test.mjs");
  EXPECT_EQ(t.exit, 0) << t.out << t.err;
  EXPECT_NE(t.out.find("# pass 17"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("# fail 0"), std::string::npos) << t.out;
}

// Hostile manifests (clients/three/test/manifest.test.mjs under node --test): every field
// kind of the documented shape refused with a WaterGraphError naming its path, through
// checkManifest and the WaterGraph constructor (a builtin "__proto__", "textures": 5, a null
// uniform, an angular_frequency "abc", a derived uniform of the removed --derived-uniforms,
// ...: before, a TypeError or a value taken silently), and parameters named __proto__ and
// constructor set as uniforms. The fixtures are what compile writes for four graphs with
// such parameters, time phases, a node texture and a scene texture.
TEST_F(ThreeClient, HostileManifestsAreRefusedNamingTheField) {
  TempDir dir("wg_three_");
  for (const char* graph : {"tests/ecosystem/data/proto_parameter.json", "graphs/topdown.json", "graphs/lagoon.json",
                            "tests/ecosystem/data/three_environment.json"}) {
    CmdResult c = wgRun("compile " + test::shellQuote(test::sourcePath(graph)) + " -o " + test::shellQuote(dir.path()) +
                        " --target es300 --quiet");
    ASSERT_EQ(c.exit, 0) << graph << ": " << c.err;
  }
  CmdResult t = sh("cd " + test::shellQuote(clientDir()) + " && WG_THREE_FIXTURES=" + test::shellQuote(dir.path()) +
                   " timeout 50 node --test test/manifest.test.mjs");
  EXPECT_EQ(t.exit, 0) << t.out << t.err;
  EXPECT_NE(t.out.find("# pass 59"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("# fail 0"), std::string::npos) << t.out;
}

// The spectral ocean's plumbing without a browser (clients/three/test/ocean.test.mjs under
// node --test): the pass order of a filtered and an unfiltered cascade, the pyramid's level
// counts, the manifest's "filtered" making every cascade of its ocean filtered, and the raw WebGL of a filtered
// cascade's pyramid replayed as GL state: the pack into level 0 of three maps, then each level
// l drawn with its samplers showing level l - 1 alone (no feedback loop), every level visible
// to the water after. Needs Node.js and the npm packages, not Chromium.
TEST(ThreeOcean, PlumbingChecksPassUnderNode) {
  if (!haveTool("node")) GTEST_SKIP() << "Node.js (node) is not on PATH";
  CmdResult n = sh(test::shellQuote(clientDir() + "/test/npm_ci_cached.sh"));
  ASSERT_EQ(n.exit, 0) << "installing clients/three's npm packages failed: " << n.err;
  CmdResult t = sh("cd " + test::shellQuote(clientDir()) + " && timeout 50 node --test test/ocean.test.mjs");
  EXPECT_EQ(t.exit, 0) << t.out << t.err;
  EXPECT_NE(t.out.find("# pass 5"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("# fail 0"), std::string::npos) << t.out;
}

// `compile --textures` writes each node texture once, as the runtime uploads it.
TEST(CompileTextures, WritesNodeTexturesAsPngBesideTheShaders) {
  TempDir dir("wg_three_");
  CmdResult c = wgRun("compile " + test::shellQuote(test::sourcePath("tests/ecosystem/data/textured_waves.json")) +
                      " -o " + test::shellQuote(dir.path()) + " --target es300 --textures --quiet");
  ASSERT_EQ(c.exit, 0) << c.err;
  auto pngs = test::listFiles(dir.path(), ".png");
  ASSERT_EQ(pngs.size(), 1u);
  EXPECT_EQ(pngs[0], "textured_waves.t0_foam.png");
  rt::Image img = rt::readPng(dir / pngs[0]);
  auto foam = generateBuiltinTexture("foam");
  ASSERT_TRUE(foam.has_value());
  ASSERT_EQ(img.width, foam->width);
  ASSERT_EQ(img.height, foam->height);
  // The PNG's last row is the texture's row 0 (v = 0), as with a PNG source file.
  size_t row = static_cast<size_t>(img.width) * 4;
  for (int y = 0; y < img.height; ++y)
    ASSERT_TRUE(std::equal(foam->rgba.begin() + static_cast<long>(static_cast<size_t>(y) * row),
                           foam->rgba.begin() + static_cast<long>(static_cast<size_t>(y + 1) * row),
                           img.rgba8.begin() + static_cast<long>(static_cast<size_t>(img.height - 1 - y) * row)))
        << "row " << y;
  // Without --textures, no PNG.
  TempDir plain("wg_three_");
  ASSERT_EQ(wgRun("compile " + test::shellQuote(test::sourcePath("tests/ecosystem/data/textured_waves.json")) +
                  " -o " + test::shellQuote(plain.path()) + " --target es300 --quiet")
                .exit,
            0);
  EXPECT_TRUE(test::listFiles(plain.path(), ".png").empty());
}

}  // namespace
}  // namespace wg::eco
#endif
