// The editor's frames in the graph file, "editor": {"frames": {...}} (docs/graph-format.md):
// loaded with their title, comment and nodes, refused with WG013 at the frame's "nodes"
// when they list no node, an unknown node, a node twice or a node another frame holds, kept
// by the canonical form (fmt) last in the file, and dropped from by the edit model when
// their nodes are deleted. Positions were worked out by hand from the texts below.
#include <gtest/gtest.h>

#include <string>

#include "core/graph_edit.h"
#include "core/graph_io.h"
#include "diagnostic_text.h"

namespace wg {
namespace {

using core_test::dump;
using core_test::lc;

// Three nodes; `editor` is the graph's "editor" member's value, spliced in before "nodes"
// (on line 2), its first character at col 11.
std::string framedGraphText(const std::string& editor) {
  return "{\"version\": 1, \"name\": \"g\",\n"
         "\"editor\": " + editor + ",\n"
         "\"nodes\": [{\"id\": \"a\", \"type\": \"uv\"}, {\"id\": \"b\", \"type\": \"fract\", \"inputs\": {\"x\": \"a.out\"}},\n"
         "          {\"id\": \"c\", \"type\": \"saturate\", \"inputs\": {\"x\": \"b.out\"}}],\n"
         "\"outputs\": {\"fragment\": {\"color\": [1, 0, 0]}}}\n";
}

struct FramedLoad {
  std::optional<Graph> graph;
  Diagnostics diags;
};

FramedLoad loadFramed(const std::string& text) {
  FramedLoad r;
  r.graph = parseGraph(text, "g.json", r.diags);
  return r;
}

Diagnostic onlyFrameError(const std::string& text, DiagCode code) {
  FramedLoad r = loadFramed(text);
  EXPECT_FALSE(r.graph) << text;
  EXPECT_EQ(r.diags.all().size(), 1u) << dump(r.diags);
  if (r.diags.all().empty()) return {};
  EXPECT_EQ(r.diags.all()[0].code, code) << dump(r.diags);
  return r.diags.all()[0];
}

TEST(FramesLoad, TitleCommentAndNodesInFileOrder) {
  FramedLoad r = loadFramed(framedGraphText(R"({"frames": {"uvs": {"title": "UV set-up", "comment": "line one\nline two", "nodes": ["b", "a"]},
                                        "tail": {"nodes": ["c"]}}})"));
  ASSERT_TRUE(r.graph) << dump(r.diags);
  ASSERT_EQ(r.graph->frames.size(), 2u);
  const Frame& f = r.graph->frames[0];
  EXPECT_EQ(f.id, "uvs");
  EXPECT_EQ(f.title, "UV set-up");
  EXPECT_EQ(f.comment, "line one\nline two");
  EXPECT_EQ(f.nodes, (std::vector<std::string>{"b", "a"}));
  EXPECT_EQ(lc(f.where), "2:23");
  EXPECT_EQ(r.graph->frames[1].id, "tail");
  EXPECT_EQ(r.graph->frames[1].title, "");
  EXPECT_TRUE(r.graph->findFrame("tail"));
  EXPECT_FALSE(r.graph->findFrame("a"));
}

TEST(FramesLoad, MalformedFramesAreRefusedWhereTheyAre) {
  // col 11 is the "editor" value's '{'; {"frames": {"f": {... puts the frame's '{' at col 28
  // and its "nodes" value at col 38.
  auto e = onlyFrameError(framedGraphText(R"({"frames": {"f": {"nodes": []}}})"), DiagCode::InvalidFrame);
  EXPECT_EQ(lc(e.where), "2:38");
  EXPECT_EQ(e.message, "frame 'f' holds no nodes; a frame lists at least one");
  e = onlyFrameError(framedGraphText(R"({"frames": {"f": {"nodes": ["a", "bb"]}}})"), DiagCode::InvalidFrame);
  EXPECT_EQ(e.message, "frame 'f' lists node 'bb', which the graph does not have (did you mean 'b'?)");
  EXPECT_EQ(lc(e.where), "2:38");
  e = onlyFrameError(framedGraphText(R"({"frames": {"f": {"nodes": ["a", "a"]}}})"), DiagCode::InvalidFrame);
  EXPECT_EQ(e.message, "frame 'f' lists node 'a' twice");
  e = onlyFrameError(framedGraphText(R"({"frames": {"f": {"nodes": ["a"]}, "g": {"nodes": ["b", "a"]}}})"), DiagCode::InvalidFrame);
  EXPECT_EQ(e.message, "frame 'g' lists node 'a', which frame 'f' holds; a node lies in at most one frame");
  e = onlyFrameError(framedGraphText(R"({"frames": {"f": {"title": "t"}}})"), DiagCode::MissingField);
  EXPECT_EQ(lc(e.where), "2:28");
  e = onlyFrameError(framedGraphText(R"({"frames": {"f": {"nodes": "a"}}})"), DiagCode::WrongJsonType);
  EXPECT_EQ(lc(e.where), "2:38");
  e = onlyFrameError(framedGraphText(R"({"frames": {"f": {"nodes": ["a"], "title": 3}}})"), DiagCode::WrongJsonType);
  EXPECT_EQ(e.message, "'title' of frame 'f' must be a string, found number");
  e = onlyFrameError(framedGraphText(R"({"frames": {"f": {"nodes": ["a"], "colour": "red"}}})"), DiagCode::UnknownField);
  EXPECT_EQ(lc(e.where), "2:45");
  e = onlyFrameError(framedGraphText(R"({"frames": {"2f": {"nodes": ["a"]}}})"), DiagCode::InvalidIdentifier);
  EXPECT_EQ(lc(e.where), "2:23");
  e = onlyFrameError(framedGraphText(R"({"frames": []})"), DiagCode::WrongJsonType);
  EXPECT_EQ(lc(e.where), "2:22");
  e = onlyFrameError(framedGraphText(R"({"groups": {}})"), DiagCode::UnknownField);
  EXPECT_EQ(lc(e.where), "2:12");
  onlyFrameError(framedGraphText(R"([])"), DiagCode::WrongJsonType);
  onlyFrameError(framedGraphText(R"({"frames": {"f": {"nodes": ["a"]}, "f": {"nodes": ["b"]}}})"), DiagCode::DuplicateKey);
}

TEST(FramesLoad, TheCanonicalFormKeepsThemLastAndReadsBackTheSame) {
  FramedLoad r = loadFramed(framedGraphText(R"({"frames": {"uvs": {"nodes": ["b", "a"], "comment": "why \"this\"\nmatters", "title": "UV"}}})"));
  ASSERT_TRUE(r.graph) << dump(r.diags);
  std::string text = saveGraph(*r.graph);
  const std::string expectedTail =
      "  \"editor\": {\n"
      "    \"frames\": {\n"
      "      \"uvs\": {\"title\": \"UV\", \"comment\": \"why \\\"this\\\"\\nmatters\", \"nodes\": [\"b\", \"a\"]}\n"
      "    }\n"
      "  }\n"
      "}\n";
  ASSERT_GE(text.size(), expectedTail.size());
  EXPECT_EQ(text.substr(text.size() - expectedTail.size()), expectedTail) << text;
  FramedLoad again = loadFramed(text);
  ASSERT_TRUE(again.graph) << dump(again.diags);
  EXPECT_EQ(saveGraph(*again.graph), text);
  ASSERT_EQ(again.graph->frames.size(), 1u);
  EXPECT_EQ(again.graph->frames[0].comment, "why \"this\"\nmatters");
  // No frames: no "editor" member at all.
  r.graph->frames.clear();
  EXPECT_EQ(saveGraph(*r.graph).find("\"editor\": {\n"), std::string::npos);
}

Graph threeNodesInFrames() {
  FramedLoad r = loadFramed(framedGraphText(R"({"frames": {"head": {"nodes": ["a", "b"]}, "tail": {"title": "end", "nodes": ["c"]}}})"));
  EXPECT_TRUE(r.graph) << dump(r.diags);
  return r.graph ? *r.graph : Graph{};
}

TEST(FramesEdit, AddTakesNodesFromOtherFramesAndDropsEmptiedOnes) {
  GraphEditor e(threeNodesInFrames());
  std::string id;
  Frame f;
  f.nodes = {"c", "b"};
  ASSERT_EQ(e.addFrame(f, &id), "");
  EXPECT_EQ(id, "frame_1");
  ASSERT_EQ(e.graph().frames.size(), 2u);  // tail lost c, its only node
  EXPECT_EQ(e.graph().frames[0].id, "head");
  EXPECT_EQ(e.graph().frames[0].nodes, std::vector<std::string>{"a"});
  EXPECT_EQ(e.graph().frames[1].nodes, (std::vector<std::string>{"c", "b"}));
  EXPECT_EQ(e.undoLabel(), "add frame 'frame_1'");
  ASSERT_TRUE(e.undo());
  EXPECT_EQ(e.graph().frames.size(), 2u);
  EXPECT_EQ(e.graph().findFrame("tail")->nodes, std::vector<std::string>{"c"});

  long revision = e.revision();
  f.nodes = {};
  EXPECT_NE(e.addFrame(f), "");
  f.nodes = {"a", "zz"};
  EXPECT_NE(e.addFrame(f), "");
  f.nodes = {"a", "a"};
  EXPECT_NE(e.addFrame(f), "");
  f.nodes = {"a"};
  f.id = "tail";
  EXPECT_NE(e.addFrame(f), "") << "a taken id";
  f.id = "no way";
  EXPECT_NE(e.addFrame(f), "");
  EXPECT_EQ(e.revision(), revision);
}

TEST(FramesEdit, TextNodesDeleteAndMoveAreOneUndoStepEach) {
  GraphEditor e(threeNodesInFrames());
  ASSERT_EQ(e.setFrameText("head", "Head", "two\nlines"), "");
  EXPECT_EQ(e.graph().findFrame("head")->comment, "two\nlines");
  EXPECT_NE(e.setFrameText("nope", "x", ""), "");
  ASSERT_EQ(e.setFrameNodes("head", {"a", "c"}), "");
  EXPECT_FALSE(e.graph().findFrame("tail")) << "emptied by taking c";
  ASSERT_TRUE(e.undo());
  EXPECT_TRUE(e.graph().findFrame("tail"));
  ASSERT_EQ(e.deleteFrame("tail"), "");
  EXPECT_FALSE(e.graph().findFrame("tail"));
  EXPECT_TRUE(e.graph().findNode("c")) << "a frame's nodes stay";
  ASSERT_TRUE(e.undo());
  ASSERT_TRUE(e.undo());
  EXPECT_EQ(e.graph().findFrame("head")->title, "");

  // Moving a frame moves its nodes by the same offset (unplaced ones from the origin).
  e.moveNode("a", {10, 20});
  e.seal();
  ASSERT_EQ(e.moveFrame("head", {5, -7}), "");
  ASSERT_EQ(e.moveFrame("head", {1, 1}), "");  // a drag: merged
  EXPECT_EQ(*e.graph().findNode("a")->editorPosition, (std::array<double, 2>{16, 14}));
  EXPECT_EQ(*e.graph().findNode("b")->editorPosition, (std::array<double, 2>{6, -6}));
  EXPECT_FALSE(e.graph().findNode("c")->editorPosition);
  ASSERT_TRUE(e.undo());
  EXPECT_EQ(*e.graph().findNode("a")->editorPosition, (std::array<double, 2>{10, 20}));

  // Deleting nodes (several at once, or one) takes them out of their frames; a frame left
  // empty goes.
  ASSERT_EQ(e.deleteNodes({"a", "c"}), "");
  EXPECT_FALSE(e.graph().findFrame("tail"));
  EXPECT_EQ(e.graph().findFrame("head")->nodes, std::vector<std::string>{"b"});
  Diagnostics d;
  EXPECT_TRUE(parseGraph(saveGraph(e.graph()), "g.json", d)) << dump(d);
  ASSERT_TRUE(e.undo());
  ASSERT_EQ(e.deleteNode("c"), "");
  EXPECT_FALSE(e.graph().findFrame("tail"));
  EXPECT_TRUE(e.graph().findFrame("head"));
}

}  // namespace
}  // namespace wg
