// The built-in scene's floating buoys (runtime/floating_buoys.h): each rides the point the
// graph's vertex stage moves its rest point to, tilted to the displaced sheet's normal
// (central differences), and the renderer draws them
// with the opaque scene; `render --buoys` floats them, and refuses where it cannot.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "codegen/compile.h"
#include "codegen/water_surface_eval.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "runtime/egl_context.h"
#include "runtime/floating_buoys.h"
#include "runtime/image.h"
#include "runtime/preview.h"
#include "runtime/renderer.h"
#include "runtime_test_support.h"
#include "test_support.h"

namespace wg::rt {
// Named, not anonymous: the unity build joins this file with the other runtime tests.
namespace buoys_test {

// Two Gerstner waves; `withNormal` writes the waves' normal in the vertex stage too.
CompileResult compileWaves(bool withNormal) {
  Diagnostics diags;
  const std::string vertex = withNormal ? R"("position": "waves.position", "normal": "waves.normal")"
                                        : R"("position": "waves.position")";
  auto graph = parseGraph(R"({"version": 1, "name": "buoys_test", "nodes": [
      {"id": "waves", "type": "gerstner_waves", "options": {"waves": [
        {"direction": [1, 0.4], "steepness": 0.5, "wavelength": 9, "amplitude": 0.5},
        {"direction": [-0.3, 1], "steepness": 0.3, "wavelength": 4, "amplitude": 0.15}]}}],
      "outputs": {"vertex": {)" + vertex + R"(}, "fragment": {"color": [0.02, 0.1, 0.15]}}})",
                          "buoys_test.json", diags);
  CompileOptions o;
  o.targets = {Target::Glsl330};
  auto result = graph ? compileGraph(*graph, defaultRegistry(), o, diags) : std::nullopt;
  if (!result) throw std::runtime_error("the test graph does not compile:\n" + diags.sorted().front().message);
  return std::move(*result);
}

std::vector<Value> defaults(const wg::Program& program) {
  std::vector<Value> v;
  for (const auto& p : program.parameters) v.push_back(p.defaultValue);
  return v;
}

// Each buoy sits where the vertex stage moves its rest point, and tilts to the normal of the
// displaced sheet: central differences 5 cm apart, the waves' own normal within their
// O(h^2) error (k h = 2 pi 0.05 / 4 = 0.079: (k h)^2 / 6 of the slope, under 1e-3).
TEST(FloatingBuoys, EachRidesThePointTheVertexStageMovesItsRestPointTo) {
  CompileResult waves = compileWaves(true), positionOnly = compileWaves(false);
  const std::vector<Value> params = defaults(waves.program);
  std::vector<FloatingPose> first;
  for (double t : {0.0, 3.5, 11.25, 1e6}) {
    const std::vector<FloatingPose> poses = floatingBuoys(waves.program, params, t);
    ASSERT_EQ(poses.size(), buoyRestPoints().size());
    // The vertex stage's own normal plays no part: a graph without one floats them alike.
    EXPECT_EQ(poses, floatingBuoys(positionOnly.program, defaults(positionOnly.program), t));
    for (size_t i = 0; i < poses.size(); ++i) {
      const WaterSurfacePoint s = waterSurfaceAt(waves.program, params, buoyRestPoints()[i].x, buoyRestPoints()[i].y, t);
      for (int k = 0; k < 3; ++k) EXPECT_EQ(poses[i].position[k], static_cast<float>(s.position[k])) << t;
      const double len = std::sqrt(s.normal[0] * s.normal[0] + s.normal[1] * s.normal[1] + s.normal[2] * s.normal[2]);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(poses[i].up[k], s.normal[k] / len, 1e-3) << "buoy " << i << " t " << t;
      EXPECT_GT(std::abs(poses[i].up.x) + std::abs(poses[i].up.z), 0.02f) << "the case must tilt the buoy";
    }
    if (first.empty()) first = poses;
  }
  // They move: heave, sway and tilt differ between t = 0 and t = 3.5 s.
  const std::vector<FloatingPose> later = floatingBuoys(waves.program, params, 3.5);
  for (size_t i = 0; i < later.size(); ++i) {
    EXPECT_GT(std::abs(later[i].position.y - first[i].position.y), 0.01f) << i;
    EXPECT_GT(std::abs(later[i].up.x - first[i].up.x) + std::abs(later[i].up.z - first[i].up.z), 0.01f) << i;
  }
}

// A vertex stage that samples a node texture (a height from builtin:foam's alpha) floats
// them too: the texture is read for the evaluation (it was an internal error).
TEST(FloatingBuoys, AVertexStageSamplingATextureFloatsThem) {
  Diagnostics diags;
  auto graph = parseGraph(R"({"version": 1, "name": "vtex", "nodes": [
      {"id": "uv", "type": "uv"},
      {"id": "tex", "type": "texture_sample", "options": {"texture": "builtin:foam"}, "inputs": {"uv": "uv.out"}},
      {"id": "p", "type": "world_position"},
      {"id": "lift", "type": "combine", "inputs": {"x": 0, "y": "tex.alpha", "z": 0}},
      {"id": "moved", "type": "add", "inputs": {"a": "p.out", "b": "lift.out"}}],
      "outputs": {"vertex": {"position": "moved.out"}, "fragment": {"color": [0.1, 0.2, 0.3]}}})",
                          "vtex.json", diags);
  ASSERT_TRUE(graph);
  auto program = buildProgram(*graph, defaultRegistry(), diags);
  ASSERT_TRUE(program);
  const std::vector<FloatingPose> poses = floatingBuoys(*program, {}, 3.5);
  ASSERT_EQ(poses.size(), buoyRestPoints().size());
  float highest = 0;
  for (size_t i = 0; i < poses.size(); ++i) {
    const WaterSurfacePoint s = waterSurfaceAt(*program, {}, buoyRestPoints()[i].x, buoyRestPoints()[i].y, 3.5);
    EXPECT_EQ(poses[i].position.y, static_cast<float>(s.position[1]));
    highest = std::max(highest, poses[i].position.y);
  }
  EXPECT_GT(highest, 0.0f) << "the texture lifts no buoy: the case does not reach the look-up";
}

// The renderer draws them with the opaque scene: a frame with buoys differs from one
// without where they float, and only there (a few hundred pixels of a 320x180 frame).
TEST(FloatingBuoys, TheRendererDrawsThemWithTheScene) {
  auto ctx = EglContext::create(GlApi::DesktopGl45);
  CompileResult waves = compileWaves(true);
  RenderSettings settings = test::smallSettings();
  Renderer plain(waves.manifest, waterShaderSources(waves, Target::Glsl330), settings, false);
  settings.scene.buoys = floatingBuoys(waves.program, defaults(waves.program), settings.scene.time);
  Renderer floating(waves.manifest, waterShaderSources(waves, Target::Glsl330), settings, false);
  plain.renderFrame();
  floating.renderFrame();
  const Image a = plain.readRgba8(), b = floating.readRgba8();
  size_t differ = 0, red = 0;
  for (size_t i = 0; i < a.rgba8.size(); i += 4) {
    const bool changed = a.rgba8[i] != b.rgba8[i] || a.rgba8[i + 1] != b.rgba8[i + 1] || a.rgba8[i + 2] != b.rgba8[i + 2];
    differ += changed;
    red += changed && b.rgba8[i] > 2 * b.rgba8[i + 1] && b.rgba8[i] > 60;  // the buoys' red bodies
  }
  EXPECT_GT(red, 30u);
  EXPECT_LT(differ, a.rgba8.size() / 4 / 20) << "more than 5 % of the frame changed";
  // Moved to another time's poses, the same renderer draws them there.
  SceneOptions later = settings.scene;
  later.time = 5.0;
  later.buoys = floatingBuoys(waves.program, defaults(waves.program), later.time);
  floating.setScene(later);
  floating.renderFrame();
  const Image c = floating.readRgba8();
  EXPECT_NE(b.rgba8, c.rgba8);
}

TEST(FloatingBuoys, RenderFloatsThemAndRefusesWhereItCannot) {
  const std::string dir = test::makeTempDir("wg_buoys");
  const std::string wg = test::shellQuote(test::watergraphBinary());
  const std::string graph = test::shellQuote(test::sourcePath("graphs/topdown.json"));
  std::string out;
  EXPECT_EQ(test::runCommand(wg + " render " + graph + " -o " + test::shellQuote(dir + "/b.png") +
                                 " --size 160x90 --buoys 2>&1",
                             &out),
            0)
      << out;
  for (const char* bad : {" --scene none", " --target vk450"}) {
    EXPECT_EQ(test::runCommand(wg + " render " + graph + " -o " + test::shellQuote(dir + "/c.png") + " --buoys" + bad + " 2>&1",
                               &out),
              2)
        << bad;
    EXPECT_NE(out.find("--buoys"), std::string::npos) << out;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace buoys_test
}  // namespace wg::rt
