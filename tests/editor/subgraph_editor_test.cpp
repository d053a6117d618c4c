// Subgraphs in the editor: a graph that imports a function graph (lib/tint.json, made in
// a temporary folder) lists it in the palette, shows its instance with the interface's
// ports, opens it for editing and comes back, follows it on disk, and lists its errors in
// its own file. The model first, then the program under xvfb-run.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "codegen/compile.h"
#include "core/graph_edit.h"
#include "core/graph_imports.h"
#include "core/graph_io.h"
#include "core/graph_node_type.h"
#include "core/resolve.h"
#include "editor/error_list.h"
#include "editor/file_watcher.h"
#include "editor/node_palette.h"
#include "core/node_preview_graph.h"
#include "editor_run.h"
#include "nodes/registry.h"
#include "runtime/image.h"
#include "test_support.h"

namespace wg::editor {
namespace {

namespace fs = std::filesystem;

// A function graph: its parameters are the instance's inputs, its interface the outputs.
const char* const kTintJson = R"({
  "version": 1,
  "name": "tint",
  "interface": {
    "description": "A colour scaled by a gain.",
    "outputs": {
      "color": {"type": "vec3", "source": "scaled.out", "description": "the colour times the gain"}
    }
  },
  "parameters": {
    "base": {"type": "vec3", "default": [0.1, 0.4, 0.5], "min": 0, "max": 1, "hint": "color"},
    "gain": {"type": "float", "default": 1, "min": 0, "max": 4}
  },
  "nodes": [
    {"id": "scaled", "type": "mul", "inputs": {"a": "$base", "b": "$gain"}}
  ]
}
)";

const char* const kPondJson = R"({
  "version": 1,
  "name": "pond",
  "imports": {"tint": "lib/tint.json"},
  "nodes": [
    {"id": "water", "type": "tint", "inputs": {"gain": 0.8}, "editor": {"x": 0, "y": 0}}
  ],
  "outputs": {"fragment": {"color": "water.color", "alpha": 1}}
}
)";

// A temporary folder with pond.json importing lib/tint.json.
struct SubgraphWorkspace {
  std::string dir = test::makeTempDir("wg_subgraph_editor");
  std::string pond = dir + "/pond.json";
  std::string tint = dir + "/lib/tint.json";
  SubgraphWorkspace() {
    fs::create_directories(dir + "/lib");
    test::writeFile(pond, kPondJson);
    test::writeFile(tint, kTintJson);
  }
  ~SubgraphWorkspace() { fs::remove_all(dir); }
  std::string path(const std::string& name) const { return dir + "/" + name; }
  std::string script(const std::string& json) const {
    test::writeFile(path("edits.json"), json);
    return "--script " + test::shellQuote(path("edits.json")) + " " + test::shellQuote(pond);
  }
  Graph load() const {
    Diagnostics d;
    auto g = loadGraphFile(pond, d);
    EXPECT_TRUE(g) << (d.all().empty() ? "" : formatText(d.all().front()));
    return g ? *g : Graph{};
  }
};

std::string tintWith(const std::string& from, const std::string& to) {
  std::string text = kTintJson;
  size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(SubgraphPalette, ListsTheGraphsImportsFirstUnderSubgraphsWithTheirDescription) {
  SubgraphWorkspace ws;
  Graph g = ws.load();
  auto entries = paletteEntries(g, defaultRegistry(), "");
  ASSERT_FALSE(entries.empty());
  EXPECT_EQ(entries.front().type, "tint");
  EXPECT_EQ(entries.front().family, kSubgraphFamily);
  EXPECT_NE(entries.front().summary.find("A colour scaled by a gain."), std::string::npos) << entries.front().summary;
  EXPECT_NE(entries.front().summary.find("lib/tint.json"), std::string::npos) << entries.front().summary;
  EXPECT_EQ(entries.size(), defaultRegistry().size() + 1) << "and every registered type";
  EXPECT_TRUE(std::any_of(entries.begin(), entries.end(), [](const PaletteEntry& e) { return e.type == "mix"; }));

  auto filtered = paletteEntries(g, defaultRegistry(), "tin");
  EXPECT_TRUE(std::any_of(filtered.begin(), filtered.end(), [](const PaletteEntry& e) { return e.type == "tint"; }));
  auto others = paletteEntries(g, defaultRegistry(), "mix");
  EXPECT_FALSE(std::any_of(others.begin(), others.end(), [](const PaletteEntry& e) { return e.family == kSubgraphFamily; }));
}

TEST(SubgraphEdit, AnInstanceHasTheInterfacesPortsConnectsAndHasNoOptions) {
  SubgraphWorkspace ws;
  Graph g = ws.load();
  const Registry& r = defaultRegistry();
  EXPECT_TRUE(nodeTypeOf(g, r, "tint").isInstance());
  EXPECT_FALSE(nodeTypeOf(g, r, "mix").isInstance());
  EXPECT_FALSE(nodeTypeOf(g, r, "ghost"));
  auto ports = portsOfGraphNode(g, r, *g.findNode("water"));
  ASSERT_TRUE(ports);
  ASSERT_EQ(ports->inputs.size(), 2u);
  EXPECT_EQ(ports->inputs[0].name, "base");
  EXPECT_EQ(ports->inputs[0].type, Type::Vec3);
  ASSERT_TRUE(ports->inputs[0].defaultValue);
  EXPECT_FLOAT_EQ(static_cast<float>((*ports->inputs[0].defaultValue)[1]), 0.4f);
  EXPECT_EQ(ports->inputs[1].name, "gain");
  ASSERT_EQ(ports->outputs.size(), 1u);
  EXPECT_EQ(ports->outputs[0].name, "color");
  EXPECT_EQ(ports->outputs[0].doc, "the colour times the gain");

  GraphEditor e(g, &r);
  std::string id;
  ASSERT_EQ(e.addNode("tint", "", {300, 0}, &id), "");
  EXPECT_EQ(id, "tint_1");
  EXPECT_EQ(e.connect("water", "color", {"tint_1", "base"}), "");
  EXPECT_NE(e.connect("water", "colour", {"tint_1", "base"}).find("has no output 'colour'"), std::string::npos);
  EXPECT_NE(e.setInputConstant({"tint_1", "bias"}, {1}).find("has no input 'bias'"), std::string::npos);
  EXPECT_NE(e.setOption("water", "model", "exact").find("no options"), std::string::npos);
  EXPECT_EQ(e.connect("tint_1", "color", {"", "fragment.color"}), "");

  // Saved, the imports stay, and the edited graph compiles with the new instance.
  std::string text = saveGraph(e.graph());
  EXPECT_NE(text.find("\"imports\""), std::string::npos) << text;
  Diagnostics d;
  auto again = parseGraph(text, ws.pond, d);
  ASSERT_TRUE(again);
  ASSERT_TRUE(loadImports(*again, d));
  EXPECT_TRUE(compileGraph(*again, r, CompileOptions{}, d)) << (d.all().empty() ? "" : formatText(d.all().front()));
}

TEST(SubgraphEdit, AdoptedImportsReachEveryUndoStateWithoutAnEdit) {
  SubgraphWorkspace ws;
  const Registry& r = defaultRegistry();
  GraphEditor e(ws.load(), &r);
  ASSERT_EQ(e.moveNode("water", {10, 10}), "");
  long revision = e.revision();
  test::writeFile(ws.tint, tintWith(R"("gain": {)", R"("boost": {"type": "float", "default": 2}, "gain": {)"));
  Graph now = e.graph();
  Diagnostics d;
  ASSERT_TRUE(loadImports(now, d));
  e.adoptImports(now);
  EXPECT_EQ(e.revision(), revision);
  auto inputs = [&] { return portsOfGraphNode(e.graph(), r, *e.graph().findNode("water"))->inputs.size(); };
  EXPECT_EQ(inputs(), 3u);
  ASSERT_TRUE(e.undo());
  EXPECT_EQ(inputs(), 3u) << "the state undo brings back sees the file as it is now";
}

TEST(SubgraphErrors, AnErrorInsideASubgraphIsListedInItsFileAndSelectsTheInstance) {
  SubgraphWorkspace ws;
  std::string bad = tintWith(R"("type": "mul")", R"("type": "mull")");
  test::writeFile(ws.tint, bad);
  Graph g = ws.load();
  Diagnostics d;
  EXPECT_FALSE(resolveGraph(g, defaultRegistry(), d));
  ASSERT_FALSE(d.all().empty());
  const Diagnostic& e = d.all().front();
  size_t at = bad.find("\"mull\"");
  int line = 1 + static_cast<int>(std::count(bad.begin(), bad.begin() + static_cast<ptrdiff_t>(at), '\n'));
  int col = static_cast<int>(at - bad.rfind('\n', at));
  std::string text = errorListText(e, ws.dir);
  std::string where = "lib/tint.json:" + std::to_string(line) + ":" + std::to_string(col) + ": error: [WG";
  EXPECT_EQ(text.rfind(where, 0), 0u) << text;
  EXPECT_NE(text.find("unknown node type 'mull'"), std::string::npos) << text;
  EXPECT_NE(text.find("\npond.json:"), std::string::npos) << text;
  EXPECT_NE(text.find("note: in instance 'water' of 'lib/tint.json'"), std::string::npos) << text;
  EXPECT_EQ(nodeToSelect(e, g), "water") << "the instance it lies in, not its inner node";

  Diagnostic own;
  own.where.file = ws.pond;
  own.node = "water";
  EXPECT_EQ(nodeToSelect(own, g), "water");
  EXPECT_EQ(errorListText(own, "/somewhere/else").rfind(ws.pond, 0), 0u) << "a file outside stays as it is";
}

TEST(SubgraphWatch, TheWatcherFollowsEveryImportedFileAndOnesThatDoNotLoad) {
  SubgraphWorkspace ws;
  Graph g = ws.load();
  EXPECT_EQ(filesToWatch(g), (std::vector<std::string>{ws.pond, ws.tint}));
  FileWatcher watcher(ws.pond);
  watcher.watch(filesToWatch(g));
  EXPECT_FALSE(watcher.changed());
  test::writeFile(ws.tint, tintWith("0.4", "0.45"));  // another size: noticed even on a coarse clock
  EXPECT_TRUE(watcher.changed());
  EXPECT_FALSE(watcher.changed()) << "once per change";
  test::writeFile(ws.tint, tintWith("0.4", "0.455"));
  watcher.acknowledge(ws.tint);  // our own save
  EXPECT_FALSE(watcher.changed());

  Graph missing = g;
  missing.imports[0].graph = nullptr;  // as when lib/tint.json did not load
  missing.imports[0].path = "lib/later.json";
  missing.imports[0].file = ws.path("lib/later.json");  // what loadImports sets for a path it tried
  EXPECT_EQ(filesToWatch(missing), (std::vector<std::string>{ws.pond, ws.path("lib/later.json")}));
}

TEST(SubgraphPreview, AnInstancesOutputAndAFunctionGraphWithoutOutputSlotsCompile) {
  SubgraphWorkspace ws;
  Graph g = ws.load();
  std::string why;
  auto thumb = nodeOutputGraph(g, defaultRegistry(), "water", "color", &why);
  ASSERT_TRUE(thumb) << why;
  Diagnostics d;
  CompileOptions o;
  o.targets = {Target::Glsl330};
  EXPECT_TRUE(compileGraph(*thumb, defaultRegistry(), o, d)) << (d.all().empty() ? "" : formatText(d.all().front()));

  Diagnostics dt;
  auto tint = loadGraphFile(ws.tint, dt);
  ASSERT_TRUE(tint);
  auto shown = interfaceOutputGraph(*tint, &why);
  ASSERT_TRUE(shown) << why;
  EXPECT_TRUE(compileGraph(*shown, defaultRegistry(), o, dt)) << (dt.all().empty() ? "" : formatText(dt.all().front()));
  auto inner = nodeOutputGraph(*tint, defaultRegistry(), "scaled", "out", &why);
  EXPECT_TRUE(inner) << "a node inside a function graph has a thumbnail too: " << why;
  EXPECT_FALSE(interfaceOutputGraph(g, &why)) << "a graph with output slots shows them";
}

// --- the program -------------------------------------------------------------------------

TEST(EditorSubgraph, OpenedEditedAndSavedTheParentComesBackCompiledWithTheChange) {
  SubgraphWorkspace ws;
  auto p = [&](const char* name) { return ws.path(name); };
  std::string pondBefore = test::readFile(ws.pond);
  test::EditorRun r = test::runEditorProgram(ws.dir, ws.script(R"([
    {"op": "save_preview", "path": ")" + p("before.png") + R"("},
    {"op": "open_subgraph", "node": "water"},
    {"op": "frames", "count": 1},
    {"op": "save_preview", "path": ")" + p("subgraph.png") + R"("},
    {"op": "set_parameter", "name": "base", "value": [1, 0.1, 0]},
    {"op": "save"},
    {"op": "back"},
    {"op": "frames", "count": 1},
    {"op": "save_preview", "path": ")" + p("after.png") + R"("},
    {"op": "add_node", "type": "tint", "id": "second", "x": 300, "y": 0},
    {"op": "connect", "from": "water.color", "to": "second.base"},
    {"op": "connect", "from": "second.color", "to_output": "fragment.color"},
    {"op": "save"}
  ])"));
  ASSERT_EQ(r.status, 0) << r.err;
  Diagnostics d;
  auto tint = loadGraphFile(ws.tint, d);
  ASSERT_TRUE(tint);
  EXPECT_EQ(tint->findParameter("base")->defaultValue, (std::vector<double>{1, 0.1, 0})) << "saved to the subgraph's file";
  EXPECT_TRUE(tint->interface) << "the interface is kept";
  rt::Image before = rt::readPng(p("before.png")), sub = rt::readPng(p("subgraph.png")), after = rt::readPng(p("after.png"));
  EXPECT_GT(rt::lumaVariance(sub, 0, 0, sub.width, sub.height), 1.0) << "the subgraph previews through its interface output";
  EXPECT_LT(rt::psnrRgb8(before, after), 30.0) << "the parent was compiled again with the saved subgraph";

  auto pond = loadGraphFile(ws.pond, d);
  ASSERT_TRUE(pond) << r.err;
  ASSERT_EQ(pond->imports.size(), 1u) << "saving the parent keeps its imports";
  EXPECT_EQ(pond->imports[0].path, "lib/tint.json");
  ASSERT_TRUE(pond->findNode("second"));
  EXPECT_NE(test::readFile(ws.pond), pondBefore);
  EXPECT_TRUE(compileGraph(*pond, defaultRegistry(), CompileOptions{}, d)) << (d.all().empty() ? "" : formatText(d.all().front()));
}

TEST(EditorSubgraph, BackRefusesToDropUnsavedChangesUnlessTold) {
  SubgraphWorkspace ws;
  std::string unsaved = R"([
    {"op": "open_subgraph", "node": "water"},
    {"op": "set_parameter", "name": "gain", "value": 2},
    {"op": "back"}
  ])";
  test::EditorRun refused = test::runEditorProgram(ws.dir, ws.script(unsaved));
  EXPECT_EQ(refused.status, 1);
  EXPECT_NE(refused.err.find("step 3 (back)"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("unsaved changes"), std::string::npos) << refused.err;

  std::string discard = R"([
    {"op": "open_subgraph", "node": "water"},
    {"op": "set_parameter", "name": "gain", "value": 2},
    {"op": "back", "discard": true},
    {"op": "open_subgraph", "node": "ghost"}
  ])";
  test::EditorRun ghost = test::runEditorProgram(ws.dir, ws.script(discard));
  EXPECT_EQ(ghost.status, 1);
  EXPECT_NE(ghost.err.find("step 4 (open_subgraph): no node 'ghost'"), std::string::npos) << ghost.err;
  EXPECT_EQ(test::readFile(ws.tint), kTintJson) << "the discarded change was never written";
}

TEST(EditorSubgraph, AChangedSubgraphFileRecompilesTheOpenParent) {
  SubgraphWorkspace ws;
  test::writeFile(ws.path("red.json"), tintWith("[0.1, 0.4, 0.5]", "[0.9, 0.1, 0]"));
  test::EditorRun r = test::runEditorProgram(ws.dir, ws.script(R"([
    {"op": "save_preview", "path": ")" + ws.path("before.png") + R"("},
    {"op": "external_write", "path": ")" + ws.tint + R"(", "from": ")" + ws.path("red.json") + R"("},
    {"op": "wait_reload"},
    {"op": "frames", "count": 1},
    {"op": "save_preview", "path": ")" + ws.path("after.png") + R"("}
  ])"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_LT(rt::psnrRgb8(rt::readPng(ws.path("before.png")), rt::readPng(ws.path("after.png"))), 30.0);
  EXPECT_EQ(test::readFile(ws.pond), kPondJson) << "the parent file is not written";
}

TEST(EditorSubgraph, AnErrorInsideASubgraphIsReportedInItsFileWithTheInstance) {
  SubgraphWorkspace ws;
  std::string bad = tintWith(R"("type": "mul")", R"("type": "mull")");
  test::writeFile(ws.path("bad.json"), bad);
  test::EditorRun r = test::runEditorProgram(ws.dir, ws.script(R"([
    {"op": "external_write", "path": ")" + ws.tint + R"(", "from": ")" + ws.path("bad.json") + R"("},
    {"op": "wait_reload"},
    {"op": "frames", "count": 1}
  ])"));
  EXPECT_EQ(r.status, 1) << "the graph, as last compiled, has errors\n" << r.err;
  size_t at = bad.find("\"mull\"");
  int line = 1 + static_cast<int>(std::count(bad.begin(), bad.begin() + static_cast<ptrdiff_t>(at), '\n'));
  int col = static_cast<int>(at - bad.rfind('\n', at));
  std::string where = ws.tint + ":" + std::to_string(line) + ":" + std::to_string(col) + ": error: [WG";
  EXPECT_NE(r.err.find(where), std::string::npos) << "want " << where << " in\n" << r.err;
  EXPECT_NE(r.err.find("note: in instance 'water' of 'lib/tint.json'"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace wg::editor
