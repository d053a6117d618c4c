// Copy, cut, paste and duplicate through the system clipboard as graph JSON
// (docs/editor.md, "Nodes"): ids made unique, links inside the copy kept, and a paste that
// cannot go in is a message, the graph and its undo history unchanged.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/graph_io.h"
#include "editor/clipboard_graph.h"
#include "editor_run.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg::editor {
namespace {

namespace fs = std::filesystem;

Graph lake() {
  Diagnostics d;
  auto g = loadGraphFile(test::sourcePath("graphs/lake.json"), d);
  EXPECT_TRUE(g);
  return g ? *g : Graph{};
}

const NodeInput* inputOf(const Node& n, const std::string& port) {
  for (const auto& in : n.inputs)
    if (in.port == port) return &in;
  return nullptr;
}

TEST(ClipboardGraph, CopiedNodesPasteWithFreshIdsAndTheirOwnLinks) {
  Graph g = lake();
  std::string text = copyNodesAsJson(g, {"depth", "tint"});
  Diagnostics d;
  auto clip = parseGraph(text, "clip.json", d);
  ASSERT_TRUE(clip) << text;
  ASSERT_EQ(clip->nodes.size(), 2u);
  EXPECT_FALSE(inputOf(*clip->findNode("depth"), "a")) << "a link from a node left out is dropped";
  EXPECT_TRUE(inputOf(*clip->findNode("tint"), "depth")) << "the link between two copied nodes stays";

  GraphEditor e(g, &defaultRegistry());
  std::vector<std::string> added;
  ASSERT_EQ(pasteNodes(e, text, {1000, 500}, &added), "");
  EXPECT_EQ(added, (std::vector<std::string>{"depth_2", "tint_2"}));
  const Node* tint2 = e.graph().findNode("tint_2");
  ASSERT_TRUE(tint2);
  EXPECT_EQ(inputOf(*tint2, "depth")->source.name, "depth_2") << "the link follows the new id";
  EXPECT_EQ(inputOf(*tint2, "deep")->source.name, "deep") << "a parameter the graph has stays";
  EXPECT_EQ(e.graph().findNode("depth_2")->editorPosition, (std::array<double, 2>{1000, 500})) << "top left at the anchor";
  ASSERT_TRUE(e.undo());
  EXPECT_FALSE(e.graph().findNode("tint_2")) << "one undo step";

  // Into a graph without the parameters: those inputs go back to their defaults.
  Graph other;
  other.name = "other";
  GraphEditor e2(other, &defaultRegistry());
  ASSERT_EQ(pasteNodes(e2, text, {0, 0}, &added), "");
  EXPECT_FALSE(inputOf(*e2.graph().findNode("tint"), "deep"));
}

TEST(ClipboardGraph, BadPastesAreRefusedWhole) {
  GraphEditor e(lake(), &defaultRegistry());
  std::string before = saveGraph(e.graph());
  auto refused = [&](const std::string& text) {
    std::vector<std::string> added;
    std::string why = pasteNodes(e, text, {0, 0}, &added);
    EXPECT_NE(why, "") << text.substr(0, 200);
    EXPECT_TRUE(added.empty());
    EXPECT_EQ(saveGraph(e.graph()), before);
    EXPECT_FALSE(e.canUndo());
    return why;
  };
  EXPECT_NE(refused("hello").find("does not hold a graph"), std::string::npos);
  EXPECT_NE(refused(R"({"version": 1, "name": "c", "nodes": [{"id": "a", "type": "frobnicate"}]})").find("frobnicate"),
            std::string::npos);
  EXPECT_NE(refused(R"({"version": 1, "name": "c", "nodes": [{"id": "a", "type": "saturate", "inputs": {"x": "b.out"}},
                          {"id": "b", "type": "saturate", "inputs": {"x": "a.out"}}]})")
                .find("cycle"),
            std::string::npos);
  EXPECT_NE(refused(R"({"version": 1, "name": "c", "nodes": [{"id": "a", "type": "add"}, {"id": "a", "type": "add"}]})"),
            "");
  std::string huge = R"({"version": 1, "name": "c", "nodes": [)";
  for (int i = 0; i < 100000; ++i) huge += std::string(i ? "," : "") + R"({"id": "n)" + std::to_string(i) + R"(", "type": "add"})";
  huge += "]}";
  EXPECT_NE(refused(huge).find("at most"), std::string::npos);
}

// The editor under Xvfb: Ctrl+C, Ctrl+V, Ctrl+X, Ctrl+D through the system clipboard, and
// bad pastes that leave the graph and Ctrl+Z as they were.
TEST(EditorClipboard, CopyCutPasteAndDuplicateThroughTheSystemClipboard) {
  std::string dir = test::makeTempDir("wg_clipboard");
  std::string graph = dir + "/lake.json";
  test::writeFile(graph, test::readFile(test::sourcePath("graphs/lake.json")));
  std::string pair = R"({\"version\": 1, \"name\": \"c\", \"nodes\": [{\"id\": \"depth\", \"type\": \"mul\"},)"
                     R"( {\"id\": \"tint\", \"type\": \"depth_tint\", \"inputs\": {\"depth\": \"depth.out\"}}]})";
  test::writeFile(dir + "/edits.json", R"([
    {"op": "frames", "count": 1},
    {"op": "select", "node": "tint"},
    {"op": "hover", "widget": "canvas", "at": [0.2, 0.9]},
    {"op": "key", "key": "c", "ctrl": true},
    {"op": "frames", "count": 1},
    {"op": "save_clipboard", "path": ")" + dir + R"(/copied.json"},
    {"op": "key", "key": "d", "ctrl": true},
    {"op": "frames", "count": 1},
    {"op": "select", "node": "fresnel"},
    {"op": "frames", "count": 1},
    {"op": "key", "key": "x", "ctrl": true},
    {"op": "frames", "count": 1},
    {"op": "save", "path": ")" + dir + R"(/cut.json"},
    {"op": "key", "key": "v", "ctrl": true},
    {"op": "frames", "count": 1},
    {"op": "set_clipboard", "text": ")" + pair + R"("},
    {"op": "key", "key": "v", "ctrl": true},
    {"op": "frames", "count": 1},
    {"op": "save"}
  ])");
  test::EditorRun r = test::runEditorProgram(dir, "--script " + test::shellQuote(dir + "/edits.json") + " " + test::shellQuote(graph));
  ASSERT_EQ(r.status, 0) << r.err;
  Diagnostics d;
  auto copied = parseGraph(test::readFile(dir + "/copied.json"), "copied.json", d);
  ASSERT_TRUE(copied) << "the clipboard holds graph JSON";
  ASSERT_EQ(copied->nodes.size(), 1u);
  EXPECT_EQ(copied->nodes[0].type, "depth_tint");
  auto cut = loadGraphFile(dir + "/cut.json", d);
  ASSERT_TRUE(cut);
  EXPECT_FALSE(cut->findNode("fresnel")) << "cut";
  EXPECT_TRUE(cut->findNode("tint_2")) << "duplicated";
  auto final = loadGraphFile(graph, d);
  ASSERT_TRUE(final);
  ASSERT_TRUE(final->findNode("fresnel")) << "pasted back under its own id (free again)";
  EXPECT_EQ(final->findNode("fresnel")->type, "fresnel");
  const Node* tint3 = final->findNode("tint_3");
  ASSERT_TRUE(tint3) << "ids made unique";
  EXPECT_EQ(inputOf(*tint3, "depth")->source.name, "depth_2") << "the link inside the paste kept";
  fs::remove_all(dir);
}

TEST(EditorClipboard, ABadPasteIsAMessageAndLeavesGraphAndUndoIntact) {
  std::string dir = test::makeTempDir("wg_clipboard_bad");
  std::string graph = dir + "/lake.json";
  std::string original = test::readFile(test::sourcePath("graphs/lake.json"));
  test::writeFile(graph, original);
  std::string cycle = R"({\"version\": 1, \"name\": \"c\", \"nodes\": [{\"id\": \"a\", \"type\": \"saturate\", \"inputs\": {\"x\": \"b.out\"}},)"
                      R"( {\"id\": \"b\", \"type\": \"saturate\", \"inputs\": {\"x\": \"a.out\"}}]})";
  std::string steps = R"([
    {"op": "set_parameter", "name": "max_depth", "value": 9},
    {"op": "frames", "count": 1},
    {"op": "hover", "widget": "canvas"})";
  for (const std::string& text : {std::string("not a graph"), std::string(R"({\"version\": 1, \"name\": \"c\", \"nodes\": [{\"id\": \"a\", \"type\": \"nope\"}]})"), cycle})
    steps += R"(, {"op": "set_clipboard", "text": ")" + text + R"("}, {"op": "key", "key": "v", "ctrl": true}, {"op": "frames", "count": 1})";
  steps += R"(, {"op": "key", "key": "z", "ctrl": true}, {"op": "frames", "count": 1}, {"op": "save"}])";
  test::writeFile(dir + "/edits.json", steps);
  test::EditorRun r = test::runEditorProgram(dir, "--script " + test::shellQuote(dir + "/edits.json") + " " + test::shellQuote(graph));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("paste refused: the clipboard does not hold a graph"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("paste refused: no node type 'nope'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("paste refused: the links among the nodes close a cycle"), std::string::npos) << r.err;
  Diagnostics d;
  auto saved = loadGraphFile(graph, d);
  ASSERT_TRUE(saved);
  EXPECT_EQ(saved->findParameter("max_depth")->defaultValue, std::vector<double>{6}) << "Ctrl+Z undid the edit before the pastes";
  EXPECT_EQ(saved->nodes.size(), 8u) << "nothing half-pasted";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace wg::editor
