// Keys and widgets as a person uses them, through the editor's scripted keys and pointer
// (docs/editor.md, "Scripted mode"): shortcuts are events (a tap shorter than a frame
// counts), the palette takes Enter and the arrows, and a value typed into a slider is
// saved as the decimal that was typed.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/graph_io.h"
#include "editor/node_palette.h"
#include "editor/slider_value.h"
#include "editor_run.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg::editor {
namespace {

namespace fs = std::filesystem;

// A temporary folder holding a copy of graphs/lake.json, and a script run on it.
struct LakeCopy {
  std::string dir = test::makeTempDir("wg_editor_input");
  std::string graph = dir + "/lake.json";
  LakeCopy() { test::writeFile(graph, test::readFile(test::sourcePath("graphs/lake.json"))); }
  ~LakeCopy() { fs::remove_all(dir); }
  std::string path(const std::string& name) const { return dir + "/" + name; }
  test::EditorRun run(const std::string& steps, const std::string& window = "640x360") const {
    test::writeFile(path("edits.json"), steps);
    return test::runEditorProgram(dir, "--script " + test::shellQuote(path("edits.json")) + " " + test::shellQuote(graph), window);
  }
  Graph saved(const std::string& name) const {
    Diagnostics d;
    auto g = loadGraphFile(path(name), d);
    EXPECT_TRUE(g) << name;
    return g ? *g : Graph{};
  }
};

TEST(SliderValue, AFloatIsKeptAsTheDecimalItShows) {
  EXPECT_EQ(decimalOfFloat(3.753f), 3.753);
  EXPECT_NE(static_cast<double>(3.753f), 3.753) << "what widening alone gives";
  EXPECT_EQ(decimalOfFloat(0.1f), 0.1);
  EXPECT_EQ(decimalOfFloat(-2.0f), -2.0);
  EXPECT_EQ(static_cast<float>(decimalOfFloat(1.17549435e-38f)), 1.17549435e-38f) << "reads back to the same float";
  // Components the widget left alone keep their exact double; the edited one is its decimal.
  std::vector<double> before{0.8, 0.123456789012345, 0.7};
  std::vector<float> shown(before.begin(), before.end());
  shown[1] = 0.25f;
  EXPECT_EQ(valuesFromWidget(before, shown), (std::vector<double>{0.8, 0.25, 0.7}));
}

TEST(EditorInput, AQuickShortcutTapBetweenTwoFramesCounts) {
  LakeCopy ws;
  // Each "key" step presses and releases before the next frame polls anything.
  test::EditorRun r = ws.run(R"([
    {"op": "set_parameter", "name": "max_depth", "value": 9},
    {"op": "key", "key": "z", "ctrl": true},
    {"op": "frames", "count": 1},
    {"op": "save", "path": ")" + ws.path("undone.json") + R"("},
    {"op": "key", "key": "y", "ctrl": true},
    {"op": "frames", "count": 1},
    {"op": "save", "path": ")" + ws.path("redone.json") + R"("}
  ])");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(ws.saved("undone.json").findParameter("max_depth")->defaultValue, std::vector<double>{6}) << "Ctrl+Z undid";
  EXPECT_EQ(ws.saved("redone.json").findParameter("max_depth")->defaultValue, std::vector<double>{9}) << "Ctrl+Y redid";
}

TEST(EditorInput, EnterAddsTheHighlightedPaletteEntryAndTheArrowsMoveIt) {
  LakeCopy ws;
  Diagnostics d;
  auto lake = loadGraphFile(ws.graph, d);
  ASSERT_TRUE(lake);
  std::vector<PaletteEntry> mixEntries = paletteEntries(*lake, defaultRegistry(), "mix");
  ASSERT_GE(mixEntries.size(), 2u);
  // Right-click the canvas background (empty there), filter, Enter; again elsewhere, Down, Enter.
  test::EditorRun r = ws.run(R"([
    {"op": "frames", "count": 1},
    {"op": "click", "widget": "canvas", "at": [0.97, 0.9], "button": "right"},
    {"op": "type", "text": "haze"},
    {"op": "key", "key": "enter"},
    {"op": "frames", "count": 1},
    {"op": "click", "widget": "canvas", "at": [0.6, 0.8], "button": "right"},
    {"op": "type", "text": "mix"},
    {"op": "key", "key": "down"},
    {"op": "key", "key": "enter"},
    {"op": "frames", "count": 1},
    {"op": "save"}
  ])", "1280x720");
  ASSERT_EQ(r.status, 0) << r.err;
  Graph g = ws.saved("lake.json");
  ASSERT_EQ(g.nodes.size(), lake->nodes.size() + 2) << test::readFile(ws.graph);
  EXPECT_EQ(g.nodes[g.nodes.size() - 2].type, "haze") << "Enter added the only match";
  EXPECT_EQ(g.nodes.back().type, mixEntries[1].type) << "Down moved to the second match";
}

TEST(EditorInput, AValueTypedIntoASliderIsSavedAsTyped) {
  LakeCopy ws;
  // Ctrl+click turns the slider into a text field; the value is typed there.
  test::EditorRun r = ws.run(R"([
    {"op": "frames", "count": 1},
    {"op": "click", "widget": "parameter max_depth", "ctrl": true},
    {"op": "key", "key": "a", "ctrl": true},
    {"op": "type", "text": "3.753"},
    {"op": "frames", "count": 1},
    {"op": "save"}
  ])");
  ASSERT_EQ(r.status, 0) << r.err;
  std::string text = test::readFile(ws.graph);
  EXPECT_NE(text.find("\"default\": 3.753,"), std::string::npos) << text.substr(0, 1200);
  EXPECT_EQ(text.find("3.753000"), std::string::npos);
  EXPECT_EQ(ws.saved("lake.json").findParameter("max_depth")->defaultValue, std::vector<double>{3.753});
}

}  // namespace
}  // namespace wg::editor
