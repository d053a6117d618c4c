// Saving after nodes were only moved keeps the file as it was written (docs/editor.md,
// "Files"): the positions change, nothing else is reformatted.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/graph_io.h"
#include "editor/graph_layout.h"
#include "editor/layout_patch.h"
#include "editor_run.h"
#include "test_support.h"

namespace wg::editor {
namespace {

namespace fs = std::filesystem;

// lake.json as a person might write it: not the canonical layout, every node placed.
std::string handWrittenLake() {
  return R"({"version": 1, "name": "lake",
  "parameters": {
    "shallow": {"type": "vec3", "default": [0, 0.8, 0.7], "min": 0, "max": 1, "hint": "color"},
    "deep":    {"type": "vec3", "default": [0, 0.1, 0.3], "min": 0, "max": 1, "hint": "color"},
    "depth_m": {"type": "float", "default": 6, "min": 0.1, "max": 50}
  },
  "nodes": [
    {"id": "uv",     "type": "uv",     "editor": {"x": 0, "y": 0}},
    {"id": "radius", "type": "length", "inputs": {"x": "uv.out"},   "editor": {"x": 220, "y": 0}},
    {"id": "tint",   "type": "depth_tint",
     "inputs": {"deep": "$deep", "depth": "radius.out", "max_depth": "$depth_m", "shallow": "$shallow"},
     "editor": { "x": 440,
                 "y": 0 }}
  ],
  "outputs": {"fragment": {"color": "tint.color", "alpha": 1}}
}
)";
}

Graph parsed(const std::string& text) {
  Diagnostics d;
  auto g = parseGraph(text, "lake.json", d);
  EXPECT_TRUE(g) << (d.all().empty() ? "" : formatText(d.all().front()));
  return g ? *g : Graph{};
}

TEST(LayoutSave, AMoveRewritesOnlyThatNodesPosition) {
  std::string text = handWrittenLake();
  Graph disk = parsed(text);
  Graph moved = disk;
  moved.nodes[2].editorPosition = std::array<double, 2>{500.5, -40};
  auto patched = patchLayoutOnly(text, disk, moved);
  ASSERT_TRUE(patched);
  std::string expected = text;
  std::string old = "{ \"x\": 440,\n                 \"y\": 0 }";
  ASSERT_NE(expected.find(old), std::string::npos);
  expected.replace(expected.find(old), old.size(), "{\"x\": 500.5, \"y\": -40}");
  EXPECT_EQ(*patched, expected);

  // A node without a position gets the one the layout gave it, inside its own object.
  std::string unplaced = text;
  std::string uvEditor = ",     \"editor\": {\"x\": 0, \"y\": 0}";
  ASSERT_NE(unplaced.find(uvEditor), std::string::npos);
  unplaced.erase(unplaced.find(uvEditor), uvEditor.size());
  Graph laidOut = parsed(unplaced);
  layoutUnplacedNodes(laidOut);
  auto withPosition = patchLayoutOnly(unplaced, laidOut, laidOut);
  ASSERT_TRUE(withPosition);
  EXPECT_EQ(saveGraph(parsed(*withPosition)), saveGraph(laidOut));
  EXPECT_NE(withPosition->find("{\"id\": \"uv\",     \"type\": \"uv\", \"editor\": {\"x\": "), std::string::npos) << *withPosition;

  // More than positions changed, or a canonical file: saved canonically (no patch).
  Graph edited = moved;
  edited.parameters[0].defaultValue = {1, 0, 0};
  EXPECT_FALSE(patchLayoutOnly(text, disk, edited));
  std::string canonical = saveGraph(disk);
  EXPECT_FALSE(patchLayoutOnly(canonical, parsed(canonical), moved));
}

TEST(LayoutSave, MovingANodeInTheEditorKeepsTheFilesFormatting) {
  std::string dir = test::makeTempDir("wg_layout_save");
  std::string graph = dir + "/lake.json";
  test::writeFile(graph, handWrittenLake());
  test::writeFile(dir + "/edits.json", R"([
    {"op": "move_node", "id": "radius", "x": 260, "y": 30},
    {"op": "save"}
  ])");
  test::EditorRun r = test::runEditorProgram(dir, "--script " + test::shellQuote(dir + "/edits.json") + " " + test::shellQuote(graph));
  ASSERT_EQ(r.status, 0) << r.err;
  std::string expected = handWrittenLake();
  std::string old = "\"editor\": {\"x\": 220, \"y\": 0}";
  expected.replace(expected.find(old), old.size(), "\"editor\": {\"x\": 260, \"y\": 30}");
  EXPECT_EQ(test::readFile(graph), expected);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace wg::editor
