// Frames on the node canvas (docs/editor.md, "Frames"): made around the selection with
// Ctrl+G, renamed and commented in their menu, dragged by the title bar with their nodes
// (one undo step), deleted (the nodes stay), saved and read back, kept by `watergraph fmt`
// and ignored by `watergraph compile`. The UI through the editor's scripted input under
// Xvfb; fmt and compile through the CLI.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <map>
#include <sstream>

#include "core/graph_edit.h"
#include "core/graph_io.h"
#include "editor/graph_change.h"
#include "editor/unreached_nodes.h"
#include "editor_run.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg::editor {
namespace {

namespace fs = std::filesystem;

// uv -> f -> len -> shade -> fragment.color, in a row.
constexpr const char* kRow = R"({
  "version": 1, "name": "row",
  "parameters": {"sh": {"type": "vec3", "default": [0, 0.5, 0.5]}},
  "nodes": [
    {"id": "uv", "type": "uv", "editor": {"x": 0, "y": 0}},
    {"id": "f", "type": "fract", "inputs": {"x": "uv.out"}, "editor": {"x": 250, "y": 0}},
    {"id": "len", "type": "length", "inputs": {"x": "f.out"}, "editor": {"x": 500, "y": 0}},
    {"id": "shade", "type": "depth_tint", "inputs": {"depth": "len.out", "shallow": "$sh"}, "editor": {"x": 750, "y": 0}}
  ],
  "outputs": {"fragment": {"color": "shade.color"}}
})";

// kRow with a frame around uv and f, written by hand (not the canonical form).
constexpr const char* kFramedRow = R"({
  "version": 1, "name": "row",
  "editor": {"frames": {"head": {"title": "Coordinates", "comment": "uv, wrapped", "nodes": ["uv", "f"]}}},
  "parameters": {"sh": {"type": "vec3", "default": [0, 0.5, 0.5]}},
  "nodes": [
    {"id": "uv", "type": "uv", "editor": {"x": 0, "y": 0}},
    {"id": "f", "type": "fract", "inputs": {"x": "uv.out"}, "editor": {"x": 250, "y": 0}},
    {"id": "len", "type": "length", "inputs": {"x": "f.out"}, "editor": {"x": 500, "y": 0}},
    {"id": "shade", "type": "depth_tint", "inputs": {"depth": "len.out", "shallow": "$sh"}, "editor": {"x": 750, "y": 0}}
  ],
  "outputs": {"fragment": {"color": "shade.color"}}
})";

struct RowDir {
  std::string dir = test::makeTempDir("wg_frames");
  std::string graph = dir + "/row.json";
  explicit RowDir(const char* text = kRow) { test::writeFile(graph, text); }
  ~RowDir() { fs::remove_all(dir); }
  test::EditorRun run(const std::string& steps) const {
    test::writeFile(dir + "/edits.json", steps);
    return test::runEditorProgram(dir, "--script " + test::shellQuote(dir + "/edits.json") + " " + test::shellQuote(graph), "1600x900");
  }
  std::string path(const std::string& name) const { return dir + "/" + name; }
  Graph saved(const std::string& name = "row.json") const {
    Diagnostics d;
    auto g = loadGraphFile(path(name), d);
    EXPECT_TRUE(g) << (d.all().empty() ? "" : formatText(d.all().front()));
    return g ? *g : Graph{};
  }
};

std::array<double, 2> at(const Graph& g, const std::string& id) {
  const Node* n = g.findNode(id);
  return n && n->editorPosition ? *n->editorPosition : std::array<double, 2>{-1e9, -1e9};
}

// The rectangles of print_widgets' report, by widget name (the last report of each).
std::map<std::string, std::array<double, 4>> widgets(const std::string& out) {
  std::map<std::string, std::array<double, 4>> rects;
  for (const std::string& line : test::splitLines(out)) {
    if (line.rfind("widget ", 0) != 0) continue;
    size_t colon = line.rfind(": ");
    std::istringstream in(line.substr(colon + 2));
    std::array<double, 4> r{};
    in >> r[0] >> r[1] >> r[2] >> r[3];
    rects[line.substr(7, colon - 7)] = r;
  }
  return rects;
}

// A box drawn from above the left of uv to below f selects those two; Ctrl+G frames them.
const std::string kSelectUvAndF = R"(
    {"op": "frames", "count": 1},
    {"op": "hover", "widget": "canvas"},
    {"op": "key", "key": "home"},
    {"op": "frames", "count": 1},
    {"op": "drag", "widget": "node uv", "from": [-0.15, -0.6], "to": [2.5, 1.3]},
    {"op": "frames", "count": 1},)";

TEST(Frames, CtrlGFramesTheSelectionAroundItsNodesAndUndoRemovesIt) {
  RowDir c;
  test::EditorRun r = c.run("[" + kSelectUvAndF + R"(
    {"op": "key", "key": "g", "ctrl": true},
    {"op": "frames", "count": 2},
    {"op": "print_widgets"},
    {"op": "save", "path": ")" + c.path("framed.json") + R"("},
    {"op": "key", "key": "z", "ctrl": true},
    {"op": "frames", "count": 1},
    {"op": "save", "path": ")" + c.path("undone.json") + R"("},
    {"op": "key", "key": "y", "ctrl": true},
    {"op": "frames", "count": 1},
    {"op": "save", "path": ")" + c.path("redone.json") + R"("}
  ])");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  Graph g = c.saved("framed.json");
  ASSERT_EQ(g.frames.size(), 1u);
  EXPECT_EQ(g.frames[0].id, "frame_1");
  EXPECT_EQ(g.frames[0].nodes, (std::vector<std::string>{"uv", "f"}));
  EXPECT_TRUE(c.saved("undone.json").frames.empty());
  EXPECT_EQ(c.saved("redone.json").frames.size(), 1u);
  // Drawn around its nodes: the title bar spans them, above them; len is outside.
  auto w = widgets(r.out);
  ASSERT_TRUE(w.count("frame frame_1") && w.count("node uv") && w.count("node f") && w.count("node len")) << r.out;
  auto title = w["frame frame_1"];
  for (const char* member : {"node uv", "node f"}) {
    EXPECT_LT(title[0], w[member][0]) << member;
    EXPECT_GT(title[2], w[member][2]) << member;
    EXPECT_LT(title[3], w[member][1]) << member;
  }
  EXPECT_LT(title[2], w["node len"][0]);
}

TEST(Frames, TheMenuRenamesCommentsAndDeletesAFrameWhoseNodesStay) {
  RowDir c;
  test::EditorRun r = c.run("[" + kSelectUvAndF + R"(
    {"op": "key", "key": "g", "ctrl": true},
    {"op": "frames", "count": 1},
    {"op": "key", "key": "home"},
    {"op": "frames", "count": 2},
    {"op": "click", "widget": "frame frame_1", "button": "right"},
    {"op": "frames", "count": 1},
    {"op": "click", "widget": "frame title field"},
    {"op": "type", "text": "Coordinates"},
    {"op": "click", "widget": "frame comment field"},
    {"op": "type", "text": "uv, wrapped"},
    {"op": "click", "widget": "frame apply"},
    {"op": "frames", "count": 2},
    {"op": "save", "path": ")" + c.path("named.json") + R"("},
    {"op": "click", "widget": "frame frame_1", "button": "right"},
    {"op": "frames", "count": 1},
    {"op": "click", "widget": "frame delete"},
    {"op": "frames", "count": 2},
    {"op": "save", "path": ")" + c.path("deleted.json") + R"("},
    {"op": "undo"},
    {"op": "save", "path": ")" + c.path("restored.json") + R"("}
  ])");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  Graph named = c.saved("named.json");
  ASSERT_EQ(named.frames.size(), 1u);
  EXPECT_EQ(named.frames[0].title, "Coordinates");
  EXPECT_EQ(named.frames[0].comment, "uv, wrapped");
  Graph deleted = c.saved("deleted.json");
  EXPECT_TRUE(deleted.frames.empty());
  EXPECT_EQ(deleted.nodes.size(), 4u) << "the frame's nodes stay";
  EXPECT_EQ(at(deleted, "uv"), at(named, "uv"));
  Graph restored = c.saved("restored.json");
  ASSERT_EQ(restored.frames.size(), 1u);
  EXPECT_EQ(restored.frames[0].comment, "uv, wrapped");
}

TEST(Frames, DraggingTheTitleBarMovesTheFramesNodesAsOneUndoStep) {
  RowDir c(kFramedRow);
  test::EditorRun r = c.run(R"([
    {"op": "frames", "count": 1},
    {"op": "hover", "widget": "canvas"},
    {"op": "key", "key": "home"},
    {"op": "frames", "count": 1},
    {"op": "drag", "widget": "frame head", "from": [0.5, 0.5], "to": [0.7, 4.5]},
    {"op": "frames", "count": 1},
    {"op": "save", "path": ")" + c.path("moved.json") + R"("},
    {"op": "key", "key": "z", "ctrl": true},
    {"op": "frames", "count": 1},
    {"op": "save", "path": ")" + c.path("undone.json") + R"("},
    {"op": "move_frame", "id": "head", "by": [-40, 25]},
    {"op": "save", "path": ")" + c.path("scripted.json") + R"("}
  ])");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  Graph moved = c.saved("moved.json");
  auto uv = at(moved, "uv"), f = at(moved, "f");
  EXPECT_GT(uv[0], 0);
  EXPECT_GT(uv[1], 0);
  EXPECT_EQ(f[0] - uv[0], 250) << "both nodes moved by the same offset";
  EXPECT_EQ(f[1], uv[1]);
  EXPECT_EQ(at(moved, "len"), (std::array<double, 2>{500, 0})) << "a node outside the frame stays";
  Graph undone = c.saved("undone.json");
  EXPECT_EQ(at(undone, "uv"), (std::array<double, 2>{0, 0})) << "one undo step";
  EXPECT_EQ(at(undone, "f"), (std::array<double, 2>{250, 0}));
  Graph scripted = c.saved("scripted.json");
  EXPECT_EQ(at(scripted, "uv"), (std::array<double, 2>{-40, 25}));
  EXPECT_EQ(at(scripted, "f"), (std::array<double, 2>{210, 25}));
}

TEST(Frames, SavedFramesReadBackAndAHandWrittenFileKeepsItsText) {
  RowDir c(kFramedRow);
  // Moving a node of a hand-written file patches its position only: the frames stay as written.
  test::EditorRun r = c.run(R"([
    {"op": "move_node", "id": "len", "x": 520, "y": 10},
    {"op": "save"}
  ])");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  std::string moved = test::readFile(c.graph);
  EXPECT_NE(moved.find("\n  \"editor\": {\"frames\": {\"head\": {\"title\": \"Coordinates\", \"comment\": \"uv, wrapped\", \"nodes\": [\"uv\", \"f\"]}}},\n"),
            std::string::npos) << moved;
  r = c.run(R"([
    {"op": "add_frame", "id": "tail", "title": "Shading", "comment": "depth\nthen tint", "nodes": ["len", "shade"]},
    {"op": "set_frame", "id": "head", "title": "UV"},
    {"op": "save"},
    {"op": "save", "path": ")" + c.path("two.json") + R"("}
  ])");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  // The frames edited: the "editor" value is written again, the rest of the text kept.
  std::string text = test::readFile(c.graph);
  EXPECT_NE(text.find("\n  \"parameters\": {\"sh\": {\"type\": \"vec3\", \"default\": [0, 0.5, 0.5]}},\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n    {\"id\": \"f\", \"type\": \"fract\", \"inputs\": {\"x\": \"uv.out\"}, \"editor\": {\"x\": 250, \"y\": 0}},\n"),
            std::string::npos) << text;
  EXPECT_NE(text, saveGraph(c.saved())) << "not reformatted";
  EXPECT_EQ(at(c.saved(), "len"), (std::array<double, 2>{520, 10}));
  EXPECT_EQ(saveGraph(c.saved()), test::readFile(c.path("two.json"))) << "the patched text reads as the canonical save";
  Graph two = c.saved("two.json");
  ASSERT_EQ(two.frames.size(), 2u);
  EXPECT_EQ(two.frames[0].title, "UV");
  EXPECT_EQ(two.frames[1].id, "tail");
  EXPECT_EQ(two.frames[1].comment, "depth\nthen tint");
  EXPECT_EQ(two.frames[1].nodes, (std::vector<std::string>{"len", "shade"}));
  // Opened and saved again, the saved file does not change.
  std::string before = test::readFile(c.path("two.json"));
  test::writeFile(c.graph, before);
  r = c.run(R"([{"op": "frames", "count": 1}, {"op": "save"}])");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  EXPECT_EQ(test::readFile(c.graph), before);
}

TEST(Frames, AFrameAddedToAHandWrittenFileWithoutOneGoesLast) {
  RowDir c;
  test::EditorRun r = c.run(R"([
    {"op": "add_frame", "id": "tail", "title": "Shading", "nodes": ["len", "shade"]},
    {"op": "save"}
  ])");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  std::string text = test::readFile(c.graph);
  // kRow ends "...}}\n}": the layout goes in before the last line break.
  std::string expected = kRow;
  expected.insert(expected.size() - 2, ",\n  \"editor\": {\"frames\": {\n    \"tail\": {\"title\": \"Shading\", \"nodes\": [\"len\", \"shade\"]}\n  }}");
  EXPECT_EQ(text, expected);
  Graph g = c.saved();
  ASSERT_EQ(g.frames.size(), 1u);
  EXPECT_EQ(g.frames[0].nodes, (std::vector<std::string>{"len", "shade"}));
}

TEST(Frames, FmtKeepsThemAndCompileIgnoresThem) {
  RowDir c(kFramedRow);
  test::CmdResult fmt = test::runWatergraph("fmt " + test::shellQuote(c.graph));
  ASSERT_EQ(fmt.exit, 0) << fmt.out << fmt.err;
  std::string formatted = test::readFile(c.graph);
  Graph g = c.saved();
  ASSERT_EQ(g.frames.size(), 1u);
  EXPECT_EQ(g.frames[0].title, "Coordinates");
  EXPECT_EQ(g.frames[0].comment, "uv, wrapped");
  EXPECT_EQ(g.frames[0].nodes, (std::vector<std::string>{"uv", "f"}));
  EXPECT_EQ(test::runWatergraph("fmt --check " + test::shellQuote(c.graph)).exit, 0);

  // The same graph with and without frames (at the top, where they shift every line after
  // them, and last, where fmt puts them) compiles to the same bytes, file for file.
  fs::create_directories(c.path("plain"));
  fs::create_directories(c.path("top"));
  fs::create_directories(c.path("last"));
  test::writeFile(c.path("plain/row.json"), kRow);
  test::writeFile(c.path("top/row.json"), kFramedRow);
  test::writeFile(c.path("last/row.json"), formatted);
  for (const char* variant : {"plain", "top", "last"}) {  // run in the folder: the shaders name the file as given
    test::CmdResult out = test::runSplit("cd " + test::shellQuote(c.path(variant)) + " && " + test::shellQuote(test::watergraphBinary()) +
                                         " compile row.json -o out");
    ASSERT_EQ(out.exit, 0) << variant << out.out << out.err;
  }
  std::vector<std::string> files = test::listFilesRecursive(c.path("plain/out"));
  ASSERT_FALSE(files.empty());
  for (const std::string& rel : files) {  // relative to the folder
    std::string plain = test::readFile(c.path("plain/out/" + rel));
    EXPECT_TRUE(test::readFile(c.path("top/out/" + rel)) == plain) << rel << " differs with the frames at the top";
    EXPECT_TRUE(test::readFile(c.path("last/out/" + rel)) == plain) << rel << " differs with the frames last";
  }
  EXPECT_EQ(test::listFilesRecursive(c.path("top/out")).size(), files.size());
}

TEST(Frames, AFrameEditIsNoRecompileAndWhatIsCompiledHasNoFrames) {
  Diagnostics d;
  auto row = parseGraph(std::string_view(kRow), "row.json", d);
  auto framed = parseGraph(std::string_view(kFramedRow), "row.json", d);
  ASSERT_TRUE(row && framed);
  GraphChange change = compareGraphs(*row, *framed);
  EXPECT_FALSE(change.structural);
  EXPECT_TRUE(change.parameters.empty());
  // A frame around a node no output reaches: the pruned graph (the preview's) still loads.
  GraphEditor e(*framed);
  ASSERT_EQ(e.addNode("uv", "lonely", {0, 300}), "");
  Frame f;
  f.nodes = {"lonely"};
  ASSERT_EQ(e.addFrame(f), "");
  Graph pruned = e.graph();
  pruneUnreachedNodes(pruned, defaultRegistry());
  EXPECT_FALSE(pruned.findNode("lonely"));
  EXPECT_TRUE(parseGraph(saveGraph(pruned), "row.json", d)) << (d.all().empty() ? "" : formatText(d.all().back()));
}

TEST(Frames, ABadFrameInTheFileIsReportedAtItsNodes) {
  RowDir c(R"({"version": 1, "name": "row",
  "nodes": [{"id": "uv", "type": "uv"}],
  "outputs": {"fragment": {"color": [1, 0, 0]}},
  "editor": {"frames": {"head": {"nodes": ["uv", "vu"]}}}})");
  test::CmdResult out = test::runWatergraph("compile " + test::shellQuote(c.graph) + " -o " + test::shellQuote(c.path("out")));
  EXPECT_EQ(out.exit, 1);
  EXPECT_NE(out.err.find("row.json:4:43: error: [WG013] frame 'head' lists node 'vu', which the graph does not have (did you mean 'uv'?)"),
            std::string::npos) << out.err;
  EXPECT_FALSE(fs::exists(c.path("out")));
}

}  // namespace
}  // namespace wg::editor
