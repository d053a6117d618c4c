// The editor's parts that draw nothing: what an edit needs (nothing, a uniform, a
// recompile), the canvas layout, the thumbnail graph of a node output, the script reader.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "codegen/compile.h"
#include "core/graph_io.h"
#include "editor/edit_script.h"
#include "editor/graph_change.h"
#include "editor/graph_layout.h"
#include "core/node_preview_graph.h"
#include "editor/orbit_camera.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg::editor {
namespace {

Graph load(const std::string& name) {
  Diagnostics d;
  auto g = loadGraphFile(test::sourcePath("graphs/" + name + ".json"), d);
  EXPECT_TRUE(g) << name;
  return g ? *g : Graph{};
}

Parameter* param(Graph& g, const std::string& name) {
  for (auto& p : g.parameters)
    if (p.name == name) return &p;
  return nullptr;
}

TEST(GraphChange, MovedNodesNeedNothingAndParameterValuesOnlyUniforms) {
  Graph a = load("lake");
  Graph b = a;
  b.nodes[0].editorPosition = std::array<double, 2>{5, 5};
  GraphChange moved = compareGraphs(a, b);
  EXPECT_FALSE(moved.structural);
  EXPECT_TRUE(moved.parameters.empty());

  param(b, "deep")->defaultValue = {1, 0, 0};
  param(b, "max_depth")->defaultValue = {7};
  GraphChange values = compareGraphs(a, b);
  EXPECT_FALSE(values.structural);
  EXPECT_EQ(values.parameters, (std::vector<std::string>{"deep", "max_depth"}));
}

TEST(GraphChange, StaticParametersLinksAndRangesRecompile) {
  Graph a = load("lake");
  Graph s = a;
  param(s, "max_depth")->isStatic = true;
  Graph s2 = s;
  param(s2, "max_depth")->defaultValue = {7};
  EXPECT_TRUE(compareGraphs(s, s2).structural) << "a static parameter is folded into the code";
  Graph r = a;
  param(r, "max_depth")->max = 20;
  EXPECT_TRUE(compareGraphs(a, r).structural);
  Graph l = a;
  l.nodes.pop_back();
  EXPECT_TRUE(compareGraphs(a, l).structural);
}

TEST(GraphLayout, PlacesUnplacedNodesInColumnsByDepthAndKeepsPlacedOnes) {
  Graph g = load("lake");
  g.nodes[1].editorPosition = std::array<double, 2>{-50, -60};
  int placed = layoutUnplacedNodes(g);
  EXPECT_EQ(placed, static_cast<int>(g.nodes.size()) - 1);
  EXPECT_EQ(g.nodes[1].editorPosition, (std::array<double, 2>{-50, -60}));
  // uv feeds from_centre feeds radius: left to right.
  auto x = [&](const char* id) { return (*g.findNode(id)->editorPosition)[0]; };
  EXPECT_LT(x("uv"), x("radius"));
  EXPECT_LT(x("radius"), x("shore"));
  EXPECT_LT(x("tint"), x("color"));
  std::set<std::array<double, 2>> distinct;
  for (const auto& n : g.nodes) distinct.insert(*n.editorPosition);
  EXPECT_EQ(distinct.size(), g.nodes.size()) << "no two nodes on top of each other";
  Graph again = load("lake");
  again.nodes[1].editorPosition = std::array<double, 2>{-50, -60};
  layoutUnplacedNodes(again);
  EXPECT_EQ(saveGraph(again), saveGraph(g)) << "deterministic";
  EXPECT_EQ(layoutUnplacedNodes(g), 0);
}

TEST(NodePreviewGraph, EveryColourableOutputOfTheExamplesCompiles) {
  int compiled = 0;
  for (const char* name : {"lake", "shelf"}) {
    Graph g = load(name);
    for (const auto& n : g.nodes) {
      const NodeSpec* spec = defaultRegistry().find(n.type);
      ASSERT_TRUE(spec);
      for (const auto& port : spec->outputs) {
        std::string why;
        auto preview = nodeOutputGraph(g, defaultRegistry(), n.id, port.name, &why);
        if (!preview) continue;  // e.g. split.w of a vec3: Invalid
        CompileOptions o;
        o.targets = {Target::Glsl330};
        Diagnostics d;
        EXPECT_TRUE(compileGraph(*preview, defaultRegistry(), o, d)) << name << " " << n.id << "." << port.name;
        ++compiled;
      }
    }
  }
  EXPECT_GE(compiled, 10);
}

TEST(NodePreviewGraph, RoutesTheOutputToTheColourAndConvertsVectors) {
  Graph g = load("lake");
  std::string why;
  auto uv = nodeOutputGraph(g, defaultRegistry(), "uv", "out", &why);  // vec2
  ASSERT_TRUE(uv) << why;
  const GraphOutput* color = nullptr;
  for (const auto& o : uv->outputs)
    if (o.slot == OutputSlot::FragmentColor) color = &o;
  ASSERT_TRUE(color);
  const Node* combine = uv->findNode(color->source.name);
  ASSERT_TRUE(combine);
  EXPECT_EQ(combine->type, "combine");
  EXPECT_EQ(saveGraph(g), saveGraph(load("lake"))) << "the original is untouched";

  EXPECT_FALSE(nodeOutputGraph(g, defaultRegistry(), "ghost", "out", &why));
  EXPECT_NE(why, "");
  EXPECT_FALSE(nodeOutputGraph(g, defaultRegistry(), "uv", "nope", &why));
}

TEST(EditScript, RefusesMalformedScriptsWithTheStep) {
  std::string dir = test::makeTempDir("wg_script");
  std::string path = dir + "/s.json";
  std::string error;
  test::writeFile(path, "{}");
  EXPECT_FALSE(loadScript(path, &error));
  EXPECT_NE(error.find("list of steps"), std::string::npos) << error;
  test::writeFile(path, R"([{"op": "save"}, {"op": "explode"}])");
  EXPECT_FALSE(loadScript(path, &error));
  EXPECT_NE(error.find("step 2: unknown op 'explode'"), std::string::npos) << error;
  test::writeFile(path, R"([{"op": "connect", "from": "uv", "to": "radius.x"}, {"op": "set_parameter", "name": "deep"}])");
  auto steps = loadScript(path, &error);
  ASSERT_TRUE(steps) << error;
  GraphEditor e(load("lake"), &defaultRegistry());
  EXPECT_NE(applyEditStep(e, (*steps)[0]).find("not \"node.port\""), std::string::npos);
  EXPECT_NE(applyEditStep(e, (*steps)[1]).find("\"value\""), std::string::npos);
  EXPECT_FALSE(e.canUndo());
  std::filesystem::remove_all(dir);
}

TEST(OrbitCamera, PresetsRoundTrip) {
  for (const auto& name : rt::cameraPresetNames()) {
    rt::Camera c = *rt::cameraPreset(name);
    rt::Camera back = OrbitCamera::fromCamera(c).toCamera();
    EXPECT_NEAR(glm::length(back.position - c.position), 0.0f, 1e-3f) << name;
    EXPECT_NEAR(glm::length(back.target - c.target), 0.0f, 1e-5f) << name;
    EXPECT_EQ(back.fovYDegrees, c.fovYDegrees) << name;
  }
}

}  // namespace
}  // namespace wg::editor
