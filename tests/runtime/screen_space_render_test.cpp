// The screen-space and scene nodes on the GL runtime (llvmpipe), both targets: a small
// graph per node runs exactly the passes its resources need and creates exactly their
// targets; the planar reflection needs no y-flip with the runtime's reflection pass; the
// deferred underwater graph renders from above and below the water without NaN, and each
// camera reaches the cases the deferred water article assigns it.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>

#include <gtest/gtest.h>

#include "codegen/compile.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "runtime/image.h"
#include "runtime/preview.h"
#include "runtime_test_support.h"
#include "test_support.h"

namespace wg::rt {
namespace {

CompileResult compileInline(const std::string& json) {
  Diagnostics diags;
  auto graph = parseGraph(json, "inline.json", diags);
  std::optional<CompileResult> r;
  if (graph) {
    CompileOptions o;
    o.targets = {Target::Glsl330, Target::Es300};
    r = compileGraph(*graph, defaultRegistry(), o, diags);
  }
  std::string messages;
  for (const auto& d : diags.all()) messages += formatText(d) + "\n";
  if (!r) ADD_FAILURE() << messages;
  return r ? std::move(*r) : CompileResult{};
}

// A graph whose colour is `expr` after the nodes `nodes` (a JSON array's contents).
std::string graphOf(const std::string& nodes, const std::string& color) {
  return R"({"version": 1, "name": "t", "nodes": [)" + nodes + R"(], "outputs": {"fragment": {"color": ")" + color +
         R"("}}})";
}

struct NodeCase {
  const char* name;
  std::string graph;
  std::vector<PassKind> passes;      // scene passes it must run (besides opaque and water)
  std::vector<std::string> targets;  // targets besides "frame"
};

std::vector<NodeCase> nodeCases() {
  return {
      {"scene_depth", graphOf(R"({"id": "d", "type": "scene_depth"},
           {"id": "s", "type": "mul", "inputs": {"a": "d.linear", "b": 0.05}})", "s.out"),
       {PassKind::DepthPrepass}, {"scene_depth"}},
      {"scene_color", graphOf(R"({"id": "c", "type": "scene_color", "inputs": {"distortion": [0.02, -0.01]}})", "c.color"),
       {PassKind::SceneColorCopy}, {"scene_color"}},
      {"planar_reflection", graphOf(R"({"id": "r", "type": "planar_reflection"})", "r.color"),
       {PassKind::PlanarReflection}, {"reflection"}},
      {"cubemap_reflection", graphOf(R"({"id": "e", "type": "cubemap_reflection"})", "e.color"),
       {PassKind::EnvironmentCubemap}, {"environment"}},
      {"ssr", graphOf(R"({"id": "e", "type": "cubemap_reflection"},
           {"id": "s", "type": "ssr", "inputs": {"fallback": "e.color"}})", "s.color"),
       {PassKind::DepthPrepass, PassKind::SceneColorCopy, PassKind::EnvironmentCubemap},
       {"scene_depth", "scene_color", "environment"}},
      {"underwater", test::readFile(test::sourcePath("graphs/deferred_underwater.json")),
       {PassKind::DepthPrepass, PassKind::SceneColorCopy, PassKind::DeferredWater, PassKind::EnvironmentCubemap},
       {"scene_depth", "scene_color", "environment", "water_normal", "water_position"}},
  };
}

class SceneNodes : public ::testing::TestWithParam<Target> {};

TEST_P(SceneNodes, EachRunsOnlyItsPassesAndRendersFinite) {
  const std::vector<PassKind> scenePasses = {PassKind::EnvironmentCubemap, PassKind::DepthPrepass,
                                             PassKind::PlanarReflection,   PassKind::Refraction,
                                             PassKind::SceneColorCopy,     PassKind::DeferredWater};
  for (const auto& c : nodeCases()) {
    SCOPED_TRACE(c.name);
    CompileResult r = compileInline(c.graph);
    RenderSettings s = test::smallSettings();
    s.environmentSize = 32;
    Preview p = renderPreview(r, GetParam(), s);
    for (PassKind k : scenePasses) {
      bool want = std::find(c.passes.begin(), c.passes.end(), k) != c.passes.end();
      EXPECT_EQ(p.plan.runs(k), want) << passName(k);
    }
    std::set<std::string> targets;
    for (const auto& t : p.plan.targets) targets.insert(t.name);
    std::set<std::string> expected(c.targets.begin(), c.targets.end());
    expected.insert({"frame", "display"});
    EXPECT_EQ(targets, expected);
    EXPECT_EQ(p.targetCount, static_cast<int>(expected.size()));
    EXPECT_GT(lumaVariance(p.image, 0, 90, 320, 180), 1.0) << "flat image";

    s.floatColor = true;
    Preview pf = renderPreview(r, GetParam(), s);
    EXPECT_EQ(countNonFinite(pf.image), 0u);
    EXPECT_EQ(pf.targetBytes, pf.plan.totalBytes());
  }
}

// Mean colour of the bottom rows (the near water of the "above" view, no objects).
std::array<double, 3> bottomMean(const Image& img, int rows) {
  std::array<double, 3> m{0, 0, 0};
  for (int y = img.height - rows; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (int k = 0; k < 3; ++k) m[k] += img.rgba8[static_cast<size_t>((y * img.width + x) * 4 + k)];
  for (double& v : m) v /= 255.0 * rows * img.width;
  return m;
}

TEST_P(SceneNodes, PlanarReflectionNeedsNoFlipWithTheRuntimesPass) {
  // The runtime renders the mirrored scene through the real camera, so the near water
  // reflects the sky high above (blue). Flipped, the same pixels would read the top of the
  // reflection image: the mirrored horizon (pale) and the ground beyond it (grey).
  auto render = [&](bool flip) {
    std::string g = graphOf(std::string(R"({"id": "r", "type": "planar_reflection", "options": {"flip_y": )") +
                                (flip ? "true" : "false") + "}}",
                            "r.color");
    return renderPreview(compileInline(g), GetParam(), test::smallSettings()).image;
  };
  auto plain = bottomMean(render(false), 18), flipped = bottomMean(render(true), 18);
  // The daylight sky reflected there lies ~20 degrees from the sun, a bright, pale blue
  // (0.84, 0.90, 0.99 shown through the sRGB output; the ground beyond the mirrored horizon
  // a grey 0.57): bluer than red by 0.1 and brighter than the flipped rows.
  EXPECT_GT(plain[2], plain[0] + 0.1) << "no flip: the reflected sky is blue";
  EXPECT_GT(plain[0] + plain[1] + plain[2], flipped[0] + flipped[1] + flipped[2] + 0.3) << "no flip: the bright sky";
  EXPECT_LT(flipped[2] - flipped[0], 0.5 * (plain[2] - plain[0])) << "flipped: the pale horizon band instead";
}

// Which of the deferred water article's cases the underwater node took per pixel, from a float render of
// case / 5.
std::set<int> casesSeen(Target target, const std::string& camera) {
  std::string g = test::readFile(test::sourcePath("graphs/deferred_underwater.json"));
  auto j = nlohmann::json::parse(g);
  j["nodes"].push_back({{"id", "which"}, {"type", "div"}, {"inputs", {{"a", "water.case"}, {"b", 5}}}});
  j["outputs"]["fragment"]["color"] = "which.out";
  RenderSettings s = test::smallSettings();
  s.camera = camera;
  s.floatColor = true;
  Preview p = renderPreview(compileInline(j.dump()), target, s);
  std::set<int> seen;
  for (size_t i = 0; i < p.image.rgba32f.size(); i += 4) seen.insert(static_cast<int>(std::lround(p.image.rgba32f[i] * 5)));
  return seen;
}

TEST_P(SceneNodes, UnderwaterReachesItsCasesFromAboveAndBelow) {
  EXPECT_EQ(casesSeen(GetParam(), "above"), (std::set<int>{1, 4}));
  EXPECT_EQ(casesSeen(GetParam(), "underwater"), (std::set<int>{2, 3}));
}

TEST_P(SceneNodes, UnderwaterRendersFiniteFromEveryCamera) {
  CompileResult r = compileInline(test::readFile(test::sourcePath("graphs/deferred_underwater.json")));
  for (const std::string& camera : cameraPresetNames()) {
    SCOPED_TRACE(camera);
    RenderSettings s = test::smallSettings();
    s.camera = camera;
    s.floatColor = true;
    Preview p = renderPreview(r, GetParam(), s);
    EXPECT_EQ(countNonFinite(p.image), 0u);
    EXPECT_TRUE(p.plan.runs(PassKind::DeferredWater));
  }
}

INSTANTIATE_TEST_SUITE_P(Targets, SceneNodes, ::testing::Values(Target::Glsl330, Target::Es300),
                         [](const auto& info) { return std::string(targetName(info.param)); });

}  // namespace
}  // namespace wg::rt
