// The blackboard (docs/editor.md, "Inspector"): parameters added, renamed with their
// references following, refused in place when the name clashes or is not an identifier,
// deleted only when nothing reads them, reordered; presets created from the current values,
// renamed, deleted. Under Xvfb, through the script's edit steps and through the inspector's
// right-click menu as a person uses it.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/graph_io.h"
#include "editor_run.h"
#include "test_support.h"

namespace wg {
namespace {

namespace fs = std::filesystem;

struct LakeDir {
  std::string dir = test::makeTempDir("wg_blackboard");
  std::string graph = dir + "/lake.json";
  LakeDir() { test::writeFile(graph, test::readFile(test::sourcePath("graphs/lake.json"))); }
  ~LakeDir() { fs::remove_all(dir); }
  test::EditorRun run(const std::string& steps) const {
    test::writeFile(dir + "/edits.json", steps);
    return test::runEditorProgram(dir, "--script " + test::shellQuote(dir + "/edits.json") + " " + test::shellQuote(graph), "1280x720");
  }
  Graph saved() const {
    Diagnostics d;
    auto g = loadGraphFile(graph, d);
    EXPECT_TRUE(g) << (d.all().empty() ? "" : formatText(d.all().front()));
    return g ? *g : Graph{};
  }
};

const InputSource* sourceOf(const Graph& g, const std::string& node, const std::string& port) {
  for (const auto& in : g.findNode(node)->inputs)
    if (in.port == port) return &in.source;
  return nullptr;
}

TEST(Blackboard, ScriptedParameterAndPresetEditsSaveAndCompile) {
  LakeDir w;
  test::EditorRun r = w.run(R"([
    {"op": "add_parameter", "name": "glint", "type": "float", "default": 0.02, "min": 0, "max": 1},
    {"op": "set_input", "node": "fresnel", "port": "f0", "parameter": "glint"},
    {"op": "rename_parameter", "name": "glint", "to": "f_zero"},
    {"op": "rename_parameter", "name": "max_depth", "to": "floor_depth"},
    {"op": "move_parameter", "name": "f_zero", "index": 0},
    {"op": "create_preset", "name": "clear"},
    {"op": "rename_preset", "name": "clear", "to": "glassy"},
    {"op": "create_preset", "name": "spare"},
    {"op": "delete_preset", "name": "spare"},
    {"op": "frames", "count": 1},
    {"op": "save"}
  ])");
  ASSERT_EQ(r.status, 0) << "the renamed graph compiles\n" << r.err;
  Graph g = w.saved();
  EXPECT_EQ(g.parameters.front().name, "f_zero");
  EXPECT_EQ(sourceOf(g, "fresnel", "f0")->name, "f_zero") << "the reference followed";
  EXPECT_EQ(sourceOf(g, "tint", "max_depth")->name, "floor_depth");
  ASSERT_TRUE(g.findPreset("glassy"));
  EXPECT_FALSE(g.findPreset("spare"));
  EXPECT_EQ(g.findPreset("glassy")->values.size(), 6u) << "every parameter's value";
}

TEST(Blackboard, ClashingOrMalformedNamesAndReadParametersAreRefused) {
  LakeDir w;
  for (const char* step : {R"({"op": "rename_parameter", "name": "max_depth", "to": "deep"})",
                           R"({"op": "rename_parameter", "name": "max_depth", "to": "max depth"})",
                           R"({"op": "delete_parameter", "name": "deep"})",
                           R"({"op": "add_parameter", "name": "sky", "type": "float"})"}) {
    test::EditorRun r = w.run(std::string("[") + step + "]");
    EXPECT_EQ(r.status, 1) << step;
    EXPECT_NE(r.err.find("edits.json: step 1"), std::string::npos) << r.err;
  }
  test::EditorRun r = w.run(R"([{"op": "delete_parameter", "name": "deep"}])");
  EXPECT_NE(r.err.find("node 'tint' input 'deep'"), std::string::npos) << "the readers are named: " << r.err;
  EXPECT_EQ(test::readFile(w.graph), test::readFile(test::sourcePath("graphs/lake.json")));
}

TEST(Blackboard, RenamingThroughTheInspectorMenuFollowsReferencesAndRefusesInPlace) {
  LakeDir w;
  // Right-click the slider, type a clashing name (refused, the dialog stays), then a good one.
  test::EditorRun r = w.run(R"([
    {"op": "frames", "count": 1},
    {"op": "click", "widget": "parameter max_depth", "button": "right"},
    {"op": "frames", "count": 1},
    {"op": "click", "widget": "blackboard field"},
    {"op": "type", "text": "deep"},
    {"op": "click", "widget": "blackboard button"},
    {"op": "frames", "count": 1},
    {"op": "save", "path": ")" + w.dir + R"(/after_clash.json"},
    {"op": "click", "widget": "blackboard field"},
    {"op": "type", "text": "_x"},
    {"op": "click", "widget": "blackboard button"},
    {"op": "frames", "count": 1},
    {"op": "save"}
  ])");
  ASSERT_EQ(r.status, 0) << r.err;
  Diagnostics d;
  auto clash = loadGraphFile(w.dir + "/after_clash.json", d);
  ASSERT_TRUE(clash);
  EXPECT_TRUE(clash->findParameter("max_depth")) << "a clashing name changes nothing";
  Graph g = w.saved();
  EXPECT_FALSE(g.findParameter("max_depth"));
  ASSERT_TRUE(g.findParameter("deep_x"));
  EXPECT_EQ(sourceOf(g, "tint", "max_depth")->name, "deep_x");
}

}  // namespace
}  // namespace wg
