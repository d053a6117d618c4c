// watergraph check on every graph in graphs/ (globbed, so new example graphs are checked
// as they arrive), both targets, at 48x27: no NaN or Inf pixel anywhere in the sweep;
// every graph but deferred water agrees with the CPU reference on its read-back inputs at
// the sampled water pixels, each within the graph's error bound. The CLI: exit 0 for the
// examples, 1 for a graph that renders NaN and for a wrong node (a constant of the lake's
// Fresnel, the pool's depth tint, the ocean's F0 changed); --error-map writes a PNG of the
// frame's size.
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "accuracy/check.h"
#include "codegen/compile.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "runtime/egl_context.h"
#include "runtime/image.h"
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

// es300 in process (no CPU comparison there: ES cannot read depth back); glsl330, with
// the comparison, through the CLI below (one pass over the graphs per target: each view
// builds a renderer, so a pass costs minutes on llvmpipe).
TEST(CheckOnGpu, EveryExampleGraphIsFiniteOverTheSweepOnEs300) {
  auto context = rt::EglContext::create(rt::apiFor(Target::Es300));
  auto graphs = test::exampleGraphs();
  ASSERT_FALSE(graphs.empty());
  for (const auto& path : graphs) {
    SCOPED_TRACE(path);
    auto result = compileFor(path, Target::Es300);
    ASSERT_TRUE(result);
    CheckOptions options;
    options.width = 48;
    options.height = 27;
    CheckReport r = checkGraph(*result, path, Target::Es300, options);
    EXPECT_EQ(r.nanInf(), 0) << formatCheckText(r);
    EXPECT_EQ(r.samples(), 0) << formatCheckText(r);
  }
}

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

// The CLI over every example graph at a small size on glsl330: exit 0 (no NaN/Inf, no
// compared pixel over its bound), one "ok" per graph, and every graph compared with the
// CPU on its read-back inputs. Each: enough pixels, none over the bound, and for forward
// water a max error under 1e-3 (a quarter of an 8-bit step; node textures are read back,
// so no filter difference remains). Deferred water's wave march samples its height map
// inside a library function, filtered by the reference itself: its max error stays under
// the graph's tolerance (2e-2) instead, each pixel held to the filter precision's bound.
TEST(CheckCli, EveryExampleGraphIsWithinItsBound) {
  std::string cmd = test::shellQuote(test::watergraphBinary()) + " check --target glsl330 --size 48x27";
  auto graphs = test::exampleGraphs();
  ASSERT_FALSE(graphs.empty());
  for (const auto& path : graphs) cmd += " " + test::shellQuote(path);
  std::string out;
  int rc = test::runCommand(cmd, &out);
  EXPECT_EQ(rc, 0) << out;
  size_t deferred = 0;
  for (const auto& path : graphs) {
    deferred += test::readFile(path).find("\"underwater\"") != std::string::npos ? 1 : 0;
    size_t header = out.find("check " + path + " on ");
    ASSERT_NE(header, std::string::npos) << path << "\n" << out;
    std::string line = out.substr(header, out.find('\n', header) - header);
    EXPECT_NE(line.find("reference: cpu"), std::string::npos) << line;
  }
  EXPECT_GT(deferred, 0u) << "an example graph with deferred water";
  size_t compared = 0;
  for (size_t at = out.find("against the cpu:"); at != std::string::npos; at = out.find("against the cpu:", at + 1)) {
    ++compared;
    std::string line = out.substr(at, out.find('\n', at) - at);
    size_t header = out.rfind("check ", at);
    ASSERT_NE(header, std::string::npos) << out;
    std::string graph = out.substr(header + 6, out.find(" on ", header) - header - 6);
    int pixels = 0, over = -1;
    double maxError = 1, meanError = 1, ratio = 1;
    ASSERT_EQ(std::sscanf(line.c_str(), "against the cpu: %d px, max %lf, mean %lf, worst error/bound %lf, over the bound %d",
                          &pixels, &maxError, &meanError, &ratio, &over),
              5)
        << line;
    EXPECT_GT(pixels, 50) << graph << ": " << line;
    EXPECT_EQ(over, 0) << graph << ": " << line;
    EXPECT_LE(ratio, 1.0) << graph << ": " << line;
    bool isDeferred = test::readFile(graph).find("\"underwater\"") != std::string::npos;
    EXPECT_LT(maxError, isDeferred ? 2e-2 : 1e-3) << graph << ": " << line;
  }
  EXPECT_EQ(compared, graphs.size()) << out;
  size_t ok = 0;
  for (size_t at = out.find("\nok: "); at != std::string::npos; at = out.find("\nok: ", at + 1)) ++ok;
  EXPECT_EQ(ok, graphs.size()) << out;
}

// Every target asked: a spectral ocean is checked on glsl330, es300 and vk450 (each runtime
// simulating it), exit 0, no NaN/Inf; vk450 alone likewise. On a small sea (one 64^2
// cascade, its foam read too); open_ocean itself is checked on vk450 by
// VulkanCheck.OpenOceanIsFiniteAndWithinItsBoundUnderValidation.
TEST(CheckCli, ASpectralOceanIsCheckedOnEveryTarget) {
  const std::string dir = test::makeTempDir("wg_check_ocean");
  const std::string graph = dir + "/small_sea.json";
  test::writeFile(graph, R"({"version": 1, "name": "small_sea", "nodes": [
      {"id": "sea", "type": "ocean_spectrum", "options": {"fft_size": 64, "tile_lengths": [40], "foam_decay": 0.4}},
      {"id": "moved", "type": "ocean_displacement", "inputs": {"ocean": "sea.ocean"}},
      {"id": "foam", "type": "ocean_foam", "inputs": {"ocean": "sea.ocean", "position": "moved.undisplaced"}},
      {"id": "color", "type": "mix", "inputs": {"a": [0, 0.1, 0.2], "b": [1, 1, 1], "t": "foam.foam"}}],
      "outputs": {"vertex": {"position": "moved.position"}, "fragment": {"color": "color.out"}}})");
  std::string out;
  int rc = test::runCommand(test::shellQuote(test::watergraphBinary()) + " check --size 32x18 " + test::shellQuote(graph), &out);
  EXPECT_EQ(rc, 0) << out;
  for (const char* target : {"glsl330", "es300", "vk450"})
    EXPECT_NE(out.find("check " + graph + " on " + target), std::string::npos) << target << "\n" << out;
  EXPECT_EQ(out.find("not run"), std::string::npos) << out;
  rc = test::runCommand(test::shellQuote(test::watergraphBinary()) + " check --size 32x18 --target vk450 " + test::shellQuote(graph),
                        &out);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_NE(out.find("check " + graph + " on vk450"), std::string::npos) << out;
  EXPECT_NE(out.find("ok: 0 NaN/Inf pixel values"), std::string::npos) << out;
  std::filesystem::remove_all(dir);
}

// A resolution per cascade (cascade_sizes): each cascade's map is read with its own texel
// scale N_c / L_c in the shaders and in the double reference. A cascade read with another
// N lands on other texels (or outside its map) and check fails its bound.
TEST(CheckCli, EachOceanCascadeIsReadAtItsOwnSize) {
  const std::string dir = test::makeTempDir("wg_check_ocean_sizes");
  const std::string graph = dir + "/sizes_sea.json";
  test::writeFile(graph, R"({"version": 1, "name": "sizes_sea", "nodes": [
      {"id": "sea", "type": "ocean_spectrum", "options": {"tile_lengths": [40, 6], "cascade_sizes": [16, 64],
       "foam_decay": 0.4}},
      {"id": "moved", "type": "ocean_displacement", "inputs": {"ocean": "sea.ocean"}},
      {"id": "surface", "type": "ocean_surface", "inputs": {"ocean": "sea.ocean", "position": "moved.undisplaced"}},
      {"id": "foam", "type": "ocean_foam", "inputs": {"ocean": "sea.ocean", "position": "moved.undisplaced"}},
      {"id": "shade", "type": "mix", "inputs": {"a": "surface.normal", "b": [1, 1, 1], "t": "foam.foam"}}],
      "outputs": {"vertex": {"position": "moved.position"}, "fragment": {"color": "shade.out"}}})");
  std::string out;
  int rc = test::runCommand(
      test::shellQuote(test::watergraphBinary()) + " check --size 32x18 --target glsl330 " + test::shellQuote(graph), &out);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_NE(out.find("ok: 0 NaN/Inf pixel values"), std::string::npos) << out;
  std::filesystem::remove_all(dir);
}

TEST(CheckCli, ErrorMapIsAPngOfTheFrameSize) {
  std::string dir = test::makeTempDir("wg_check_map");
  std::string map = dir + "/lake-error.png";
  std::string out;
  int rc = test::runCommand(test::shellQuote(test::watergraphBinary()) + " check " +
                                test::shellQuote(test::sourcePath("graphs/lake.json")) +
                                " --target glsl330 --size 40x24 --error-map " + test::shellQuote(map),
                            &out);
  EXPECT_EQ(rc, 0) << out;
  ASSERT_TRUE(std::filesystem::exists(map)) << out;
  rt::Image img = rt::readPng(map);
  EXPECT_EQ(img.width, 40);
  EXPECT_EQ(img.height, 24);
  int compared = 0, notCompared = 0;
  for (size_t i = 0; i + 3 < img.rgba8.size(); i += 4) {
    // Not compared: the frame darkened, its blue lifted to 64 and more (red and green stay below).
    bool blue = img.rgba8[i + 2] >= 64 && img.rgba8[i] < 64 && img.rgba8[i + 1] < 64;
    bool grey = img.rgba8[i] == img.rgba8[i + 1] && img.rgba8[i + 1] == img.rgba8[i + 2];
    notCompared += blue ? 1 : 0;
    compared += grey ? 1 : 0;
  }
  EXPECT_GT(compared, 0) << "no pixel of the map was compared";
  EXPECT_GT(notCompared, 0) << "every pixel compared: the sky and silhouettes should not be";
  std::filesystem::remove_all(dir);
}

// One error map per graph and target (--target all wrote the three targets' maps to one
// file, each replacing the last).
TEST(CheckCli, ErrorMapsOfSeveralTargetsAndGraphsDoNotReplaceEachOther) {
  std::string dir = test::makeTempDir("wg_check_maps");
  std::string lake = test::shellQuote(test::sourcePath("graphs/lake.json"));
  std::string out;
  int rc = test::runCommand(test::shellQuote(test::watergraphBinary()) + " check " + lake + " " +
                                test::shellQuote(test::sourcePath("graphs/shelf.json")) +
                                " --target all --size 16x9 --error-map " + test::shellQuote(dir + "/m.png"),
                            &out);
  EXPECT_EQ(rc, 0) << out;
  for (const char* g : {"lake", "shelf"})
    for (const char* t : {"glsl330", "vk450"})  // es300 compares nothing against the CPU: no map
      EXPECT_TRUE(std::filesystem::exists(dir + "/m-" + g + "-" + t + ".png")) << g << " " << t << "\n" << out;
  std::filesystem::remove_all(dir);
}

// Two graphs of one file name would write one FILE-GRAPH.png: refused before rendering.
TEST(CheckCli, TwoGraphsOfOneFileNameAreRefusedWithAnErrorMap) {
  std::string dir = test::makeTempDir("wg_check_clash");
  std::string lake = test::shellQuote(test::sourcePath("graphs/lake.json"));
  std::string out;
  std::filesystem::create_directories(dir + "/copy");
  std::filesystem::copy_file(test::sourcePath("graphs/lake.json"), dir + "/copy/lake.json");
  int rc = test::runCommand(test::shellQuote(test::watergraphBinary()) + " check " + lake + " " +
                                test::shellQuote(dir + "/copy/lake.json") + " --target glsl330 --size 16x9 --error-map " +
                                test::shellQuote(dir + "/n.png"),
                            &out);
  EXPECT_EQ(rc, 2) << out;
  EXPECT_NE(out.find("would both write the error map"), std::string::npos) << out;
  EXPECT_FALSE(std::filesystem::exists(dir + "/n-lake.png"));
  std::filesystem::remove_all(dir);
}

// A wrong node fails check: the lake's Schlick F0 0.02 -> 0.0201 in the water shader moves
// the colour by ~5e-5, over the bound at the compared pixels.
TEST(CheckCli, FailsWhenANodeIsWrong) {
  std::string out;
  int rc = test::runCommand(test::shellQuote(test::watergraphBinary()) + " check " +
                                test::shellQuote(test::sourcePath("graphs/lake.json")) +
                                " --target glsl330 --size 48x27 --mutate " +
                                test::shellQuote("wg_fresnel_schlick(n8_fresnel_t0, 0.02)=>wg_fresnel_schlick(n8_fresnel_t0, 0.0201)"),
                            &out);
  EXPECT_EQ(rc, 1) << out;
  EXPECT_NE(out.find("FAIL"), std::string::npos) << out;
  EXPECT_EQ(out.find("over the bound 0\n"), std::string::npos) << out;
}

}  // namespace
}  // namespace wg::accuracy

namespace wg::accuracy {
namespace {

// A wrong node fails check where the reference needs read-back inputs: the pool's depth
// tint (fed by the scene depth and scene colour look-ups) with its shallow colour 1 ->
// 0.999, and the ocean's Schlick F0 0.02 -> 0.04 (on the Gerstner-displaced surface, whose
// position and normal arrive as varyings; the graph's normal_map_scroll holds it to 1e-2).
TEST(CheckCli, FailsWhenANodeIsWrongOnReadBackInputs) {
  const std::pair<const char*, const char*> cases[] = {
      {"graphs/pool.json", "mix(vec3(1.0), n15_tint_color, n16_tint_t0)=>mix(vec3(0.999), n15_tint_color, n16_tint_t0)"},
      {"graphs/ocean.json", "wg_fresnel_schlick(n9_body_fresnel_t0, 0.02)=>wg_fresnel_schlick(n9_body_fresnel_t0, 0.04)"},
  };
  for (const auto& [graph, mutation] : cases) {
    SCOPED_TRACE(graph);
    std::string out;
    int rc = test::runCommand(test::shellQuote(test::watergraphBinary()) + " check " +
                                  test::shellQuote(test::sourcePath(graph)) + " --target glsl330 --size 48x27 --mutate " +
                                  test::shellQuote(mutation),
                              &out);
    EXPECT_EQ(rc, 1) << out;
    EXPECT_NE(out.find("reference: cpu"), std::string::npos) << out;
    EXPECT_EQ(out.find("over the bound 0\n"), std::string::npos) << out;
  }
}

}  // namespace
}  // namespace wg::accuracy

namespace wg::accuracy {
namespace {

// Deferred water against the CPU (every pixel at 64x36, --error-map): the graph as written passes,
// and each break of a look-up the shader makes at a position of its own fails: the
// refraction offset of the underwater node reversed, the SSR march's view depth scaled by
// 1.05, and the SSR hit's colour read at (v, u). The reference samples the read-back
// scene depth and colour images at those positions (core/scene_image.h).
// Every pixel at 32x18: the deferred read-back (G-buffer locals, whole scene images, the
// filter-precision term) within its bound. The sanitizer run's sibling of the test below.
TEST(CheckCli, DeferredWaterIsComparedWithTheCpu) {
  std::string dir = test::makeTempDir("wg_check_deferred_small");
  std::string out;
  int rc = test::runCommand(test::shellQuote(test::watergraphBinary()) + " check " +
                                test::shellQuote(test::sourcePath("graphs/deferred_underwater.json")) +
                                " --target glsl330 --size 32x18 --error-map " + test::shellQuote(dir + "/map.png"),
                            &out);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_NE(out.find("reference: cpu"), std::string::npos) << out;
  EXPECT_NE(out.find("over the bound 0\n"), std::string::npos) << out;
  std::filesystem::remove_all(dir);
}

// A graph whose scene passes run at half the frame's size ("pass_scales"): check says it
// compares at full scene resolution, renders them so (its read-back takes the scene images
// a texel per frame pixel), and the shaders, which the resolution does not change, are
// within their bound.
TEST(CheckCli, ReducedScenePassesAreCheckedAtFullResolutionAndSaySo) {
  std::string dir = test::makeTempDir("wg_check_half");
  nlohmann::json graph = nlohmann::json::parse(test::readFile(test::sourcePath("graphs/deferred_underwater.json")));
  for (auto& node : graph["nodes"]) {
    const NodeSpec* spec = defaultRegistry().find(node["type"].get<std::string>());
    if (spec && spec->optionIndex(kResolutionOption) >= 0) node["options"][kResolutionOption] = 0.5;
  }
  test::writeFile(dir + "/half.json", graph.dump(2));
  std::string out;
  int rc = test::runCommand(test::shellQuote(test::watergraphBinary()) + " check " + test::shellQuote(dir + "/half.json") +
                                " --target glsl330 --size 32x18",
                            &out);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_NE(out.find("  compared at full scene resolution: the graph renders depth_prepass at 0.5, scene_color_copy at "
                     "0.5, deferred_water at 0.5 of the frame's size; check renders every scene pass at the frame's size\n"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("reference: cpu"), std::string::npos) << out;
  EXPECT_NE(out.find("over the bound 0\n"), std::string::npos) << out;
  std::filesystem::remove_all(dir);
}

TEST(CheckCli, DeferredWaterIsComparedAndFailsWhenALookUpIsWrong) {
  std::string dir = test::makeTempDir("wg_check_deferred");
  const std::string base = test::shellQuote(test::watergraphBinary()) + " check " +
                           test::shellQuote(test::sourcePath("graphs/deferred_underwater.json")) +
                           " --target glsl330 --size 64x36 --error-map " + test::shellQuote(dir + "/map.png");
  std::string out;
  int rc = test::runCommand(base, &out);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_NE(out.find("reference: cpu"), std::string::npos) << out;
  EXPECT_NE(out.find("over the bound 0\n"), std::string::npos) << out;
  const char* mutations[] = {
      "vec2 ruv = wg_scene_color_uv(uv, strength=>vec2 ruv = wg_scene_color_uv(uv, -strength",
      "float diff = -vp.z - =>float diff = -vp.z * 1.05 - ",
      "textureLod(u_scene_color, n7_ssr_t2.xy, 0.0)=>textureLod(u_scene_color, n7_ssr_t2.yx, 0.0)",
  };
  for (const char* mutation : mutations) {
    SCOPED_TRACE(mutation);
    rc = test::runCommand(base + " --mutate " + test::shellQuote(mutation), &out);
    EXPECT_EQ(rc, 1) << out;
    EXPECT_NE(out.find("reference: cpu"), std::string::npos) << out;
    size_t at = out.find("against the cpu:");
    ASSERT_NE(at, std::string::npos) << out;
    int over = 0;
    ASSERT_EQ(std::sscanf(out.c_str() + out.find("over the bound ", at), "over the bound %d", &over), 1) << out;
    EXPECT_GT(over, 0) << out;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace wg::accuracy
