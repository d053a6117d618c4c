// New graph from the template, and save as (docs/editor.md, "Files").
#include <gtest/gtest.h>

#include <filesystem>

#include "core/graph_io.h"
#include "editor/graph_template.h"
#include "editor_run.h"
#include "runtime/image.h"
#include "test_support.h"

namespace wg {
namespace {

namespace fs = std::filesystem;

TEST(GraphTemplate, IsCanonicalAndNamedAfterTheFile) {
  std::string text = editor::newGraphText("canal");
  Diagnostics d;
  auto g = parseGraph(text, "canal.json", d);
  ASSERT_TRUE(g) << text;
  EXPECT_EQ(g->name, "canal");
  EXPECT_EQ(saveGraph(*g), text);
  EXPECT_FALSE(g->parameters.empty());
}

TEST(EditorFiles, NewStartsAGraphFromTheTemplateThatShowsAtOnce) {
  std::string dir = test::makeTempDir("wg_new_graph");
  std::string graph = dir + "/canal.json";
  test::writeFile(dir + "/edits.json", R"([{"op": "save_preview", "path": ")" + dir + R"(/preview.png"}])");
  test::EditorRun r = test::runEditorProgram(dir, "--new --script " + test::shellQuote(dir + "/edits.json") + " " + test::shellQuote(graph));
  ASSERT_EQ(r.status, 0) << "the template compiles\n" << r.err;
  Diagnostics d;
  auto g = loadGraphFile(graph, d);
  ASSERT_TRUE(g);
  EXPECT_EQ(g->name, "canal");
  rt::Image preview = rt::readPng(dir + "/preview.png");
  EXPECT_GT(rt::lumaVariance(preview, 0, 0, preview.width, preview.height), 5.0) << "water on screen";

  test::EditorRun again = test::runEditorProgram(dir, "--new " + test::shellQuote(graph));
  EXPECT_EQ(again.status, 2);
  EXPECT_NE(again.err.find("exists already"), std::string::npos) << again.err;
  test::EditorRun missing = test::runEditorProgram(dir, test::shellQuote(dir + "/nothing.json"));
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("--new creates one"), std::string::npos) << missing.err;
  fs::remove_all(dir);
}

TEST(EditorFiles, SaveAsWritesTheNewFileAndEditsItFromThen) {
  std::string dir = test::makeTempDir("wg_save_as");
  std::string lake = dir + "/lake.json", copy = dir + "/lake_copy.json";
  std::string original = test::readFile(test::sourcePath("graphs/lake.json"));
  test::writeFile(lake, original);
  test::writeFile(dir + "/edits.json", R"([
    {"op": "set_parameter", "name": "max_depth", "value": 9},
    {"op": "save_as", "path": ")" + copy + R"("},
    {"op": "set_parameter", "name": "centre_depth", "value": 3},
    {"op": "key", "key": "s", "ctrl": true},
    {"op": "frames", "count": 1}
  ])");
  test::EditorRun r = test::runEditorProgram(dir, "--script " + test::shellQuote(dir + "/edits.json") + " " + test::shellQuote(lake));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(test::readFile(lake), original) << "the file it came from stays as it was";
  Diagnostics d;
  auto g = loadGraphFile(copy, d);
  ASSERT_TRUE(g);
  EXPECT_EQ(g->findParameter("max_depth")->defaultValue, std::vector<double>{9});
  EXPECT_EQ(g->findParameter("centre_depth")->defaultValue, std::vector<double>{3}) << "Ctrl+S saved the new file";
  fs::remove_all(dir);
}

TEST(EditorFiles, AGraphThatImportsIsSavedAsOnlyInItsFolder) {
  std::string dir = test::makeTempDir("wg_save_as_imports");
  fs::copy(test::sourcePath("graphs/lib"), dir + "/lib", fs::copy_options::recursive);
  test::writeFile(dir + "/river.json", test::readFile(test::sourcePath("graphs/river.json")));
  fs::create_directories(dir + "/elsewhere");
  test::writeFile(dir + "/edits.json", R"([{"op": "save_as", "path": ")" + dir + R"(/elsewhere/river.json"}])");
  test::EditorRun r = test::runEditorProgram(dir, "--script " + test::shellQuote(dir + "/edits.json") + " " + test::shellQuote(dir + "/river.json"));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("same folder"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/elsewhere/river.json"));
  fs::remove_all(dir);
}

// Open and open recent: the graphs opened are remembered (with --settings), the "recent"
// list opens one, and unsaved changes are not let go without being asked.
TEST(EditorFiles, OpenRecentSwitchesGraphsAndRemembersThem) {
  std::string dir = test::makeTempDir("wg_recent");
  std::string lake = dir + "/lake.json", other = dir + "/other.json", settings = dir + "/settings.json";
  std::string original = test::readFile(test::sourcePath("graphs/lake.json"));
  test::writeFile(lake, original);
  test::writeFile(other, original);
  test::writeFile(dir + "/edits.json", R"([
    {"op": "set_parameter", "name": "max_depth", "value": 7},
    {"op": "open", "path": ")" + other + R"("},
    {"op": "save"},
    {"op": "open", "path": ")" + other + R"("},
    {"op": "set_parameter", "name": "max_depth", "value": 8},
    {"op": "save"},
    {"op": "frames", "count": 1},
    {"op": "click", "widget": "recent"},
    {"op": "frames", "count": 1},
    {"op": "click", "widget": "recent 0"},
    {"op": "frames", "count": 2},
    {"op": "set_parameter", "name": "max_depth", "value": 11},
    {"op": "save"}
  ])");
  test::EditorRun r = test::runEditorProgram(dir, "--settings " + test::shellQuote(settings) + " --script " +
                                                      test::shellQuote(dir + "/edits.json") + " " + test::shellQuote(lake));
  // Step 2 is refused: lake.json has unsaved changes.
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("step 2 (open): "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("unsaved changes"), std::string::npos) << r.err;

  test::writeFile(dir + "/edits.json", R"([
    {"op": "open", "path": ")" + other + R"("},
    {"op": "set_parameter", "name": "max_depth", "value": 8},
    {"op": "save"},
    {"op": "frames", "count": 1},
    {"op": "click", "widget": "recent"},
    {"op": "frames", "count": 1},
    {"op": "click", "widget": "recent 0"},
    {"op": "frames", "count": 2},
    {"op": "set_parameter", "name": "max_depth", "value": 11},
    {"op": "save"}
  ])");
  r = test::runEditorProgram(dir, "--settings " + test::shellQuote(settings) + " --script " + test::shellQuote(dir + "/edits.json") +
                                      " " + test::shellQuote(lake));
  ASSERT_EQ(r.status, 0) << r.err;
  Diagnostics d;
  EXPECT_EQ(loadGraphFile(other, d)->findParameter("max_depth")->defaultValue, std::vector<double>{8});
  EXPECT_EQ(loadGraphFile(lake, d)->findParameter("max_depth")->defaultValue, std::vector<double>{11})
      << "the recent list opened lake.json again";
  std::string remembered = test::readFile(settings);
  EXPECT_LT(remembered.find(lake), remembered.find(other)) << "the last opened first:\n" << remembered;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace wg
