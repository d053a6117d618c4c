// Half-wired graphs (docs/editor.md, "Half-wired nodes"): a node no output reaches is not
// compiled; its unconnected required inputs are warnings drawn on the node, and the preview
// and the thumbnails of the wired nodes stay live.
#include <gtest/gtest.h>

#include <filesystem>

#include "codegen/compile.h"
#include "core/graph_io.h"
#include "editor/unreached_nodes.h"
#include "editor_run.h"
#include "nodes/registry.h"
#include "runtime/image.h"
#include "test_support.h"

namespace wg::editor {
namespace {

namespace fs = std::filesystem;

Graph lakeWith(const std::string& extraNodes) {
  std::string text = test::readFile(test::sourcePath("graphs/lake.json"));
  size_t nodes = text.find("\"nodes\": [");
  EXPECT_NE(nodes, std::string::npos);
  text.insert(nodes + 10, extraNodes + ",");
  Diagnostics d;
  auto g = parseGraph(text, test::sourcePath("graphs/lake.json"), d);
  EXPECT_TRUE(g) << (d.all().empty() ? "" : formatText(d.all().front()));
  return g ? *g : Graph{};
}

TEST(HalfWired, UnreachedNodesArePrunedAndTheirMissingInputsAreWarnings) {
  const Registry& registry = defaultRegistry();
  // `hz` half-wired (color fed, distance not), `feed` reaches only hz, `spare` nothing.
  Graph g = lakeWith(R"({"id": "feed", "type": "add", "inputs": {"a": "radius.out"}},
    {"id": "hz", "type": "haze", "inputs": {"color": "tint.out"}},
    {"id": "spare", "type": "haze"})");
  Diagnostics whole;
  EXPECT_FALSE(compileGraph(g, registry, {}, whole)) << "the compiler itself refuses the unwired haze (WG023)";
  size_t before = g.nodes.size();
  Graph pruned = g;
  std::vector<Diagnostic> warnings = pruneUnreachedNodes(pruned, registry);
  EXPECT_EQ(pruned.nodes.size(), before - 3);
  for (const char* gone : {"feed", "hz", "spare"}) EXPECT_FALSE(pruned.findNode(gone)) << gone;
  for (const char* kept : {"uv", "radius", "shore", "tint", "fresnel", "color"}) EXPECT_TRUE(pruned.findNode(kept)) << kept;
  ASSERT_EQ(warnings.size(), 3u);  // hz.distance, spare.color, spare.distance
  EXPECT_EQ(warnings[0].node, "hz");
  EXPECT_EQ(warnings[0].port, "input 'distance'");
  EXPECT_EQ(warnings[0].code, DiagCode::MissingInput);
  EXPECT_EQ(warnings[0].severity, Severity::Warning);
  EXPECT_EQ(warnings[0].where, g.findNode("hz")->where) << "at the node in the file";
  EXPECT_EQ(warnings[1].node, "spare");
  EXPECT_EQ(warnings[2].port, "input 'distance'");
  Diagnostics d;
  EXPECT_TRUE(compileGraph(pruned, registry, {}, d)) << (d.all().empty() ? "" : formatText(d.all().front()));

  // A node kept on purpose (the thumbnail's) keeps what it reads.
  Graph kept = g;
  pruneUnreachedNodes(kept, registry, {"hz"});
  EXPECT_TRUE(kept.findNode("hz"));
  EXPECT_FALSE(kept.findNode("feed"));
  EXPECT_FALSE(kept.findNode("spare"));
}

TEST(HalfWired, AFunctionGraphKeepsWhatItsInterfaceReads) {
  const Registry& registry = defaultRegistry();
  Diagnostics d;
  auto g = parseGraph(R"({"version": 1, "name": "f", "parameters": {"k": {"type": "float", "default": 1}},
    "interface": {"outputs": {"foam": {"type": "float", "source": "m.out"}}},
    "nodes": [{"id": "m", "type": "mul", "inputs": {"a": "$k", "b": 2}}, {"id": "loose", "type": "haze"}]})",
                      "f.json", d);
  ASSERT_TRUE(g) << (d.all().empty() ? "" : formatText(d.all().front()));
  auto warnings = pruneUnreachedNodes(*g, registry);
  EXPECT_TRUE(g->findNode("m"));
  EXPECT_FALSE(g->findNode("loose"));
  EXPECT_EQ(warnings.size(), 2u);
}

// The editor under Xvfb: a haze node added from the palette and not wired yet leaves the
// preview live (a parameter change still reaches it), the thumbnails of wired nodes work,
// the run ends with status 0 (no errors) and the node is marked on the canvas.
TEST(HalfWired, AnUnwiredNodeLeavesThePreviewAndThumbnailsLive) {
  std::string dir = test::makeTempDir("wg_half_wired");
  std::string graph = dir + "/lake.json";
  test::writeFile(graph, test::readFile(test::sourcePath("graphs/lake.json")));
  auto p = [&](const char* name) { return dir + "/" + name; };
  test::writeFile(p("edits.json"), R"([
    {"op": "save_preview", "path": ")" + p("before.png") + R"("},
    {"op": "add_node", "type": "haze", "id": "hz", "x": -30, "y": -30},
    {"op": "frames", "count": 1},
    {"op": "set_parameter", "name": "shallow", "value": [1, 0.2, 0]},
    {"op": "set_parameter", "name": "deep", "value": [0.6, 0, 0.1]},
    {"op": "frames", "count": 1},
    {"op": "save_preview", "path": ")" + p("after.png") + R"("},
    {"op": "select", "node": "tint"},
    {"op": "frames", "count": 1},
    {"op": "save_thumbnail", "path": ")" + p("tint.png") + R"("},
    {"op": "select", "node": ""},
    {"op": "screenshot", "path": ")" + p("window.png") + R"("}
  ])");
  test::EditorRun r = test::runEditorProgram(dir, "--script " + test::shellQuote(p("edits.json")) + " " + test::shellQuote(graph));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("warning: [WG023] required input 'color' of haze is not connected"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(node 'hz', input 'distance')"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find(": error: "), std::string::npos) << r.err;
  ASSERT_TRUE(fs::exists(p("after.png")));
  EXPECT_LT(rt::psnrRgb8(rt::readPng(p("before.png")), rt::readPng(p("after.png"))), 30.0)
      << "the parameter change reached the preview";
  ASSERT_TRUE(fs::exists(p("tint.png"))) << "the wired node's thumbnail";
  EXPECT_GT(rt::lumaVariance(rt::readPng(p("tint.png")), 0, 0, 192, 108), 5.0);
  // The half-wired node's required inputs are drawn in the warning colour (255, 160, 60).
  rt::Image window = rt::readPng(p("window.png"));
  size_t warningPixels = 0;
  for (size_t i = 0; i + 3 < window.rgba8.size(); i += 4)
    warningPixels += window.rgba8[i] == 255 && window.rgba8[i + 1] == 160 && window.rgba8[i + 2] == 60;
  EXPECT_GT(warningPixels, 50u) << "the warning is drawn on the node";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace wg::editor
