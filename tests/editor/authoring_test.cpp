// Authoring edits (docs/editor.md, "Authoring"): delete with reconnection of pass-throughs,
// a node inserted into a link, an expression's inputs declared and renamed with the formula
// following, and a texture chosen from the PNG files under the graph's folder. The edit
// model is tested directly (with the node registry); the keys, the link menu, the input
// list and the picker through the editor's scripted input under Xvfb.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "core/graph_io.h"
#include "core/graph_node_type.h"
#include "core/resolve.h"
#include "editor/dissolve_nodes.h"
#include "editor/expression_inputs.h"
#include "editor/function_node_ports.h"
#include "editor/function_template.h"
#include "editor/link_insert.h"
#include "editor/texture_choices.h"
#include "editor_run.h"
#include "nodes/registry.h"
#include "runtime/image.h"
#include "test_support.h"

namespace wg::editor {
namespace {

namespace fs = std::filesystem;

// uv -> f (fract) -> s (saturate) -> len (length) -> m (mul, a second link on b) -> tint;
// m2 has a vector constant on its other generic input; shade (depth_tint) has one linked
// vec3 input and feeds the colour output; e is an expression over t and k.
constexpr const char* kChain = R"({
  "version": 1, "name": "chain",
  "parameters": {"k": {"type": "float", "default": 1}, "sh": {"type": "vec3", "default": [0, 0.5, 0.5]}},
  "nodes": [
    {"id": "uv", "type": "uv", "editor": {"x": 0, "y": 0}},
    {"id": "f", "type": "fract", "inputs": {"x": "uv.out"}, "editor": {"x": 200, "y": 0}},
    {"id": "s", "type": "saturate", "inputs": {"x": "f.out"}, "editor": {"x": 400, "y": 0}},
    {"id": "len", "type": "length", "inputs": {"x": "s.out"}, "editor": {"x": 600, "y": 0}},
    {"id": "m", "type": "mul", "inputs": {"a": "len.out", "b": "$k"}, "editor": {"x": 800, "y": 0}},
    {"id": "m2", "type": "mul", "inputs": {"a": "len.out", "b": [1, 2, 3]}, "editor": {"x": 800, "y": 200}},
    {"id": "shade", "type": "depth_tint", "inputs": {"depth": "m.out", "shallow": "$sh"}, "editor": {"x": 1000, "y": 0}},
    {"id": "e", "type": "expression", "options": {"formula": "k * t + vec3(k.t) * t", "inputs": {"k": "vec3", "t": "float"}},
     "inputs": {"k": "shade.color", "t": "len.out"}, "editor": {"x": 1200, "y": 0}},
    {"id": "sink", "type": "add", "inputs": {"a": "m2.out", "b": "e.out"}, "editor": {"x": 1400, "y": 0}}
  ],
  "outputs": {"fragment": {"color": "shade.color"}}
})";

Graph chainGraph() {
  Diagnostics d;
  auto g = parseGraph(std::string_view(kChain), "chain.json", d);
  EXPECT_TRUE(g) << (d.all().empty() ? "" : formatText(d.all().front()));
  return g ? *g : Graph{};
}

const InputSource* authoredSource(const Graph& g, const std::string& node, const std::string& port) {
  const Node* n = g.findNode(node);
  if (!n) return nullptr;
  for (const auto& in : n->inputs)
    if (in.port == port) return &in.source;
  return nullptr;
}

std::string fedBy(const Graph& g, const std::string& node, const std::string& port) {
  const InputSource* s = authoredSource(g, node, port);
  if (!s) return "(none)";
  if (s->kind == InputSource::Kind::Parameter) return "$" + s->name;
  if (s->kind == InputSource::Kind::NodeOutput) return s->name + "." + s->port;
  return "(constant)";
}

std::string graphText(const Graph& g) { return saveGraph(g); }

TEST(DeleteReconnect, AGenericPassThroughIsBridgedAsOneUndoStep) {
  const Registry& r = defaultRegistry();
  GraphEditor e(chainGraph(), &r);
  std::string before = graphText(e.graph());
  int reconnected = 0;
  ASSERT_EQ(dissolveNodes(e, r, {"s"}, &reconnected), "");
  EXPECT_FALSE(e.graph().findNode("s"));
  EXPECT_EQ(fedBy(e.graph(), "len", "x"), "f.out") << "saturate's reader now reads what fed saturate";
  EXPECT_EQ(reconnected, 1);
  ASSERT_TRUE(e.undo());
  EXPECT_EQ(graphText(e.graph()), before) << "one undo step brings it all back";
  EXPECT_FALSE(e.canUndo());
}

TEST(DeleteReconnect, ChainsOfRemovedNodesAreFollowedUpstream) {
  const Registry& r = defaultRegistry();
  GraphEditor e(chainGraph(), &r);
  ASSERT_EQ(dissolveNodes(e, r, {"s", "f"}), "");
  EXPECT_EQ(fedBy(e.graph(), "len", "x"), "uv.out");
  ASSERT_TRUE(e.undo());
  EXPECT_TRUE(e.graph().findNode("f") && e.graph().findNode("s"));
}

TEST(DeleteReconnect, AFixedTypePassThroughCarriesAParameterToAnOutputSlot) {
  const Registry& r = defaultRegistry();
  GraphEditor e(chainGraph(), &r);
  // shade: vec3 color out; of its vec3 inputs only `shallow` is linked ($sh).
  ASSERT_EQ(dissolveNodes(e, r, {"shade"}), "");
  ASSERT_EQ(e.graph().outputs.size(), 1u);
  EXPECT_EQ(e.graph().outputs[0].source.kind, InputSource::Kind::Parameter);
  EXPECT_EQ(e.graph().outputs[0].source.name, "sh");
  EXPECT_EQ(fedBy(e.graph(), "e", "k"), "$sh");
}

TEST(DeleteReconnect, AmbiguousOrTypeChangingNodesAreDisconnectedAsByDelete) {
  const Registry& r = defaultRegistry();
  {
    GraphEditor e(chainGraph(), &r);  // mul with two linked inputs: which one?
    ASSERT_EQ(dissolveNodes(e, r, {"m"}), "");
    EXPECT_EQ(fedBy(e.graph(), "shade", "depth"), "(none)");
  }
  {
    GraphEditor e(chainGraph(), &r);  // b = (1, 2, 3) made the output a vec3
    ASSERT_EQ(dissolveNodes(e, r, {"m2"}), "");
    EXPECT_EQ(fedBy(e.graph(), "sink", "a"), "(none)");
  }
  {
    GraphEditor e(chainGraph(), &r);  // length: a vector in, a float out
    ASSERT_EQ(dissolveNodes(e, r, {"len"}), "");
    EXPECT_EQ(fedBy(e.graph(), "m", "a"), "(none)");
    EXPECT_EQ(fedBy(e.graph(), "e", "t"), "(none)");
  }
  GraphEditor e(chainGraph(), &r);
  long revision = e.revision();
  EXPECT_NE(dissolveNodes(e, r, {"s", "nope"}), "");
  EXPECT_EQ(e.revision(), revision) << "refused whole";
  EXPECT_TRUE(e.graph().findNode("s"));
}

TEST(LinkInsert, ANodeGoesIntoALinkAsOneUndoStep) {
  const Registry& r = defaultRegistry();
  GraphEditor e(chainGraph(), &r);
  std::string before = graphText(e.graph());
  std::string id;
  ASSERT_EQ(insertNodeOnLink(e, r, "normalize", {"len", "x"}, {500, 100}, &id), "");
  EXPECT_EQ(id, "normalize_1");
  EXPECT_EQ(fedBy(e.graph(), id, "x"), "s.out");
  EXPECT_EQ(fedBy(e.graph(), "len", "x"), id + ".out");
  // Into an output slot; the fixed vec3 output meets depth_tint's first vec3 input.
  ASSERT_EQ(insertNodeOnLink(e, r, "depth_tint", {"", "fragment.color"}, {1100, 100}, &id), "");
  EXPECT_EQ(fedBy(e.graph(), id, "shallow"), "shade.color");
  EXPECT_EQ(e.graph().outputs[0].source.name, id);
  ASSERT_TRUE(e.undo() && e.undo());
  EXPECT_EQ(graphText(e.graph()), before);
  EXPECT_NE(insertNodeOnLink(e, r, "normalize", {"shade", "shallow"}, {0, 0}), "") << "a parameter is not a link";
  EXPECT_NE(insertNodeOnLink(e, r, "uv", {"len", "x"}, {0, 0}), "") << "uv has no input";
  EXPECT_EQ(graphText(e.graph()), before);
}

TEST(ExpressionInputs, ARenameCarriesThePortAndTheFormulaAlong) {
  std::string out;
  ASSERT_EQ(renameFormulaReferences("t+tt+t.t+t(t)*(t)", "t", "w", &out), "");
  EXPECT_EQ(out, "w+tt+w.t+t(w)*(w)") << "swizzles and calls are not references";
  EXPECT_NE(renameFormulaReferences("t # 1", "t", "w", &out), "");

  const Registry& r = defaultRegistry();
  GraphEditor e(chainGraph(), &r);
  std::string before = graphText(e.graph());
  ASSERT_EQ(renameExpressionInput(e, r, "e", "t", "amount"), "");
  const Node* n = e.graph().findNode("e");
  nlohmann::json opts = writtenOptions(*n);
  EXPECT_EQ(opts["formula"], "k * amount + vec3(k.t) * amount");
  EXPECT_EQ(opts["inputs"], nlohmann::json({{"k", "vec3"}, {"amount", "float"}}));
  EXPECT_EQ(fedBy(e.graph(), "e", "amount"), "len.out");
  Diagnostics d;
  EXPECT_TRUE(resolveGraph(e.graph(), r, d)) << (d.all().empty() ? "" : formatText(d.all().front()));
  ASSERT_TRUE(e.undo());
  EXPECT_EQ(graphText(e.graph()), before) << "one undo step";

  long revision = e.revision();
  EXPECT_NE(renameExpressionInput(e, r, "e", "t", "k"), "") << "taken";
  EXPECT_NE(renameExpressionInput(e, r, "e", "t", "2t"), "") << "not an identifier";
  EXPECT_NE(renameExpressionInput(e, r, "e", "q", "w"), "") << "not declared";
  EXPECT_NE(renameExpressionInput(e, r, "s", "x", "w"), "") << "not an expression";
  EXPECT_EQ(e.revision(), revision);
}

TEST(ExpressionInputs, DeclareRetypeAndRemoveChangeThePorts) {
  const Registry& r = defaultRegistry();
  GraphEditor e(chainGraph(), &r);
  ASSERT_EQ(declareExpressionInput(e, r, "e", "bias", Type::Vec2), "");
  auto ports = portsOfGraphNode(e.graph(), r, *e.graph().findNode("e"));
  ASSERT_TRUE(ports);
  std::vector<std::string> names;
  for (const auto& p : ports->inputs) names.push_back(p.name + ":" + std::string(typeName(p.type)));
  EXPECT_EQ(names, (std::vector<std::string>{"bias:vec2", "k:vec3", "t:float"}));
  ASSERT_EQ(retypeExpressionInput(e, r, "e", "bias", Type::Vec4), "");
  EXPECT_EQ(writtenOptions(*e.graph().findNode("e"))["inputs"]["bias"], "vec4");
  EXPECT_NE(declareExpressionInput(e, r, "e", "bias", Type::Float), "") << "declared already";
  ASSERT_EQ(removeExpressionInput(e, r, "e", "t"), "");
  EXPECT_EQ(fedBy(e.graph(), "e", "t"), "(none)") << "what fed it goes with it";
}

// A folder with a graph, PNG files (one in a subfolder, one in a hidden folder), a file
// named .png that is not one, and a link to a PNG outside.
struct TextureDir {
  std::string dir = test::makeTempDir("wg_texpick");
  std::string outside = test::makeTempDir("wg_texpick_out");
  TextureDir() {
    rt::Image img;
    img.width = img.height = 4;
    img.rgba8.assign(64, 200);
    fs::create_directories(dir + "/sub");
    fs::create_directories(dir + "/.hidden");
    rt::writePng(dir + "/a.png", img);
    rt::writePng(dir + "/sub/b.png", img);
    rt::writePng(dir + "/.hidden/c.png", img);
    rt::writePng(outside + "/far.png", img);
    test::writeFile(dir + "/fake.png", "not a png");
    fs::create_symlink(outside + "/far.png", dir + "/away.png");
    fs::create_symlink(dir + "/a.png", dir + "/near.png");
    test::writeFile(dir + "/tex.json", R"({"version": 1, "name": "tex",
      "nodes": [{"id": "sample", "type": "texture_sample", "options": {"texture": "builtin:foam"}}],
      "outputs": {"fragment": {"color": "sample.rgb"}}})");
  }
  ~TextureDir() { fs::remove_all(dir), fs::remove_all(outside); }
};

TEST(TexturePicker, ListsThePngFilesTheLoaderAcceptsAndRefusesTheRest) {
  TextureDir t;
  TextureChoices c = listGraphTextures(t.dir);
  EXPECT_EQ(c.paths, (std::vector<std::string>{"a.png", "near.png", "sub/b.png"}));
  EXPECT_FALSE(c.truncated);
  const Registry& r = defaultRegistry();
  Diagnostics d;
  auto g = loadGraphFile(t.dir + "/tex.json", d);
  ASSERT_TRUE(g);
  GraphEditor e(*g, &r);
  ASSERT_EQ(chooseTexture(e, r, t.dir, "sample", "texture", "sub/b.png"), "");
  EXPECT_EQ(writtenOptions(*e.graph().findNode("sample"))["texture"], "sub/b.png");
  long revision = e.revision();
  for (const char* bad : {"away.png", "../wg_x.png", "/etc/passwd", "fake.png", "missing.png"})
    EXPECT_NE(chooseTexture(e, r, t.dir, "sample", "texture", bad), "") << bad;
  EXPECT_NE(chooseTexture(e, r, t.dir, "sample", "wrap", "a.png"), "") << "not a texture option";
  EXPECT_EQ(e.revision(), revision);
}

std::vector<std::string> portNames(const std::vector<PortSpec>& ports) {
  std::vector<std::string> names;
  for (const auto& p : ports) names.push_back(p.name + ":" + std::string(typeName(p.type)));
  return names;
}

TEST(FunctionNode, ATemplateWritesACompilingFileAndThePortsFollowItsEdits) {
  std::string dir = test::makeTempDir("wg_fnnode");
  test::writeFile(dir + "/g.json", R"({"version": 1, "name": "g", "nodes": [{"id": "uv", "type": "uv"}],
    "outputs": {"fragment": {"color": [0.5, 0.5, 0.5]}}})");
  const Registry& r = defaultRegistry();
  Diagnostics d;
  auto g = loadGraphFile(dir + "/g.json", d);
  ASSERT_TRUE(g);
  GraphEditor e(*g, &r);
  std::string id;
  ASSERT_EQ(addFunctionNodeFromTemplate(e, r, dir, "ripple", {300, 0}, &id), "");
  EXPECT_EQ(id, "glsl_function_1");
  EXPECT_EQ(test::readFile(dir + "/ripple.glsl"), functionTemplateText("ripple"));
  const Node* n = e.graph().findNode(id);
  EXPECT_EQ(writtenOptions(*n), nlohmann::json({{"file", "ripple.glsl"}, {"function", "ripple"}}));
  auto ports = editorPortsOf(e.graph(), r, *n);
  ASSERT_TRUE(ports);
  EXPECT_EQ(portNames(ports->inputs), (std::vector<std::string>{"uv:vec2", "scale:float"}));
  EXPECT_EQ(portNames(ports->outputs), (std::vector<std::string>{"out:vec3"}));
  auto registryPorts = portsOfGraphNode(e.graph(), r, *n);
  EXPECT_TRUE(!registryPorts || registryPorts->inputs.empty()) << "the registry alone knows no ports of the file";
  // Wired to the output, it compiles (glslang accepted the template).
  ASSERT_EQ(e.connect("uv", "out", {id, "uv"}), "");
  ASSERT_EQ(e.setInputConstant({id, "scale"}, {4}), "");
  ASSERT_EQ(e.connect(id, "out", {"", "fragment.color"}), "");
  Diagnostics compiled;
  EXPECT_TRUE(resolveGraph(e.graph(), r, compiled)) << (compiled.all().empty() ? "" : formatText(compiled.all().front()));
  EXPECT_EQ(functionFilesOf(e.graph(), r), (std::vector<std::string>{(fs::path(dir) / "ripple.glsl").lexically_normal().string()}));

  // The file saved with another signature: the ports follow (a sampler2D adds a texture option).
  test::writeFile(dir + "/ripple.glsl", "vec4 ripple(vec2 uv, sampler2D tex, out float height) { height = uv.x;\n"
                                        "  return texture(tex, uv); }\n");
  ports = editorPortsOf(e.graph(), r, *e.graph().findNode(id));
  ASSERT_TRUE(ports);
  EXPECT_EQ(portNames(ports->inputs), (std::vector<std::string>{"uv:vec2"}));
  EXPECT_EQ(portNames(ports->outputs), (std::vector<std::string>{"out:vec4", "height:float"}));
  auto spec = fileNodeSpecOf(e.graph(), r, *e.graph().findNode(id));
  ASSERT_TRUE(spec);
  EXPECT_GE(spec->optionIndex("tex"), 0);

  long revision = e.revision();
  EXPECT_NE(addFunctionNodeFromTemplate(e, r, dir, "ripple", {0, 0}), "") << "an existing file is never overwritten";
  EXPECT_NE(addFunctionNodeFromTemplate(e, r, dir, "wg_mine", {0, 0}), "") << "reserved";
  EXPECT_NE(addFunctionNodeFromTemplate(e, r, dir, "no way", {0, 0}), "");
  EXPECT_EQ(e.revision(), revision);
  EXPECT_FALSE(fs::exists(dir + "/wg_mine.glsl"));
  fs::remove_all(dir);
}

// The chain graph in a folder, and scripts run on it at 1600x900.
struct ChainDir {
  std::string dir = test::makeTempDir("wg_authoring");
  std::string graph = dir + "/chain.json";
  ChainDir() { test::writeFile(graph, kChain); }
  ~ChainDir() { fs::remove_all(dir); }
  test::EditorRun run(const std::string& steps, const std::string& file = "") const {
    test::writeFile(dir + "/edits.json", steps);
    return test::runEditorProgram(dir, "--script " + test::shellQuote(dir + "/edits.json") + " " +
                                           test::shellQuote(file.empty() ? graph : file), "1600x900");
  }
  Graph saved(const std::string& file = "") const {
    Diagnostics d;
    auto g = loadGraphFile(file.empty() ? graph : file, d);
    EXPECT_TRUE(g) << (d.all().empty() ? "" : formatText(d.all().front()));
    return g ? *g : Graph{};
  }
};

TEST(Authoring, CtrlDeleteReconnectsAndPlainDeleteDoesNot) {
  ChainDir c;
  test::EditorRun r = c.run(R"([
    {"op": "frames", "count": 1},
    {"op": "key", "key": "home"},
    {"op": "frames", "count": 1},
    {"op": "click", "widget": "node s"},
    {"op": "key", "key": "delete", "ctrl": true},
    {"op": "frames", "count": 1},
    {"op": "save", "path": ")" + c.dir + R"(/reconnected.json"},
    {"op": "click", "widget": "node f"},
    {"op": "key", "key": "delete"},
    {"op": "frames", "count": 1},
    {"op": "save", "path": ")" + c.dir + R"(/plain.json"},
    {"op": "undo"}
  ])");
  ASSERT_EQ(r.status, 0) << r.err;
  Graph a = c.saved(c.dir + "/reconnected.json");
  EXPECT_FALSE(a.findNode("s"));
  EXPECT_EQ(fedBy(a, "len", "x"), "f.out");
  Graph b = c.saved(c.dir + "/plain.json");
  EXPECT_FALSE(b.findNode("f"));
  EXPECT_EQ(fedBy(b, "len", "x"), "(none)");
}

// Issue 43's measure: after "frame all", wiring a new node between two nodes far apart on
// the canvas takes at most 3 interactions: right-click the link, type the type, Enter.
TEST(Authoring, WiringANodeBetweenTwoFarApartTakesThreeInteractionsAfterFrameAll) {
  ChainDir c;
  // len moved far from s first, so the link between them spans the canvas.
  const std::string interactions = R"(
    {"op": "click", "widget": "link len.x", "button": "right"},
    {"op": "type", "text": "normalize"},
    {"op": "key", "key": "enter"},)";
  size_t count = 0;
  for (size_t at = interactions.find("\"op\""); at != std::string::npos; at = interactions.find("\"op\"", at + 1)) ++count;
  ASSERT_LE(count, 3u);
  test::EditorRun r = c.run(R"([
    {"op": "move_node", "id": "len", "x": 4000, "y": 1500},
    {"op": "frames", "count": 1},
    {"op": "hover", "widget": "canvas"},
    {"op": "key", "key": "home"},
    {"op": "frames", "count": 1},)" + interactions + R"(
    {"op": "frames", "count": 1},
    {"op": "save"}
  ])");
  ASSERT_EQ(r.status, 0) << r.err;
  Graph g = c.saved();
  EXPECT_EQ(fedBy(g, "normalize_1", "x"), "s.out");
  EXPECT_EQ(fedBy(g, "len", "x"), "normalize_1.out");
}

TEST(Authoring, RenamingAnExpressionInputInTheInspectorRewritesTheFormula) {
  ChainDir c;
  test::EditorRun r = c.run(R"([
    {"op": "select", "node": "e"},
    {"op": "frames", "count": 2},
    {"op": "click", "widget": "expression input t", "at": [0.9, 0.5]},
    {"op": "type", "text": "_amount"},
    {"op": "frames", "count": 1},
    {"op": "click", "widget": "expression new input"},
    {"op": "frames", "count": 1},
    {"op": "save", "path": ")" + c.dir + R"(/renamed.json"},
    {"op": "type", "text": "k"},
    {"op": "click", "widget": "expression add input"},
    {"op": "frames", "count": 1},
    {"op": "save", "path": ")" + c.dir + R"(/clash.json"},
    {"op": "click", "widget": "expression new input", "at": [0.9, 0.5]},
    {"op": "type", "text": "_gain"},
    {"op": "click", "widget": "expression add input"},
    {"op": "frames", "count": 1},
    {"op": "save"}
  ])");
  ASSERT_EQ(r.status, 0) << r.err;
  // Leaving the name field renamed the input: its port and the formula followed.
  Graph renamed = c.saved(c.dir + "/renamed.json");
  nlohmann::json opts = writtenOptions(*renamed.findNode("e"));
  EXPECT_EQ(opts["formula"], "k * t_amount + vec3(k.t) * t_amount");
  EXPECT_EQ(opts["inputs"], nlohmann::json({{"k", "vec3"}, {"t_amount", "float"}}));
  EXPECT_EQ(fedBy(renamed, "e", "t_amount"), "len.out");
  EXPECT_EQ(writtenOptions(*c.saved(c.dir + "/clash.json").findNode("e")), opts) << "a taken name is refused";
  Graph g = c.saved();
  EXPECT_EQ(writtenOptions(*g.findNode("e"))["inputs"], nlohmann::json({{"k", "vec3"}, {"t_amount", "float"}, {"k_gain", "float"}}));
}

TEST(Authoring, TheTexturePickerSetsThePathTheGraphFormatUses) {
  TextureDir t;
  ChainDir c;
  test::EditorRun r = c.run(R"([
    {"op": "select", "node": "sample"},
    {"op": "frames", "count": 2},
    {"op": "click", "widget": "texture picker texture"},
    {"op": "frames", "count": 2},
    {"op": "click", "widget": "texture choice sub/b.png"},
    {"op": "frames", "count": 1},
    {"op": "screenshot", "path": ")" + c.dir + R"(/picked.png"},
    {"op": "choose_texture", "node": "sample", "option": "texture", "path": "away.png"}
  ])", t.dir + "/tex.json");
  EXPECT_NE(r.status, 0) << "a texture outside the folder is refused";
  EXPECT_NE(r.err.find("away.png"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(c.dir + "/picked.png"));
  // The picked path reached the graph before the refused step: save it by a second run.
  r = c.run(R"([
    {"op": "select", "node": "sample"},
    {"op": "frames", "count": 2},
    {"op": "click", "widget": "texture picker texture"},
    {"op": "frames", "count": 2},
    {"op": "click", "widget": "texture choice sub/b.png"},
    {"op": "frames", "count": 1},
    {"op": "save"}
  ])", t.dir + "/tex.json");
  ASSERT_EQ(r.status, 0) << r.err;
  Graph g = c.saved(t.dir + "/tex.json");
  EXPECT_EQ(writtenOptions(*g.findNode("sample"))["texture"], "sub/b.png");
}

// The heights of the box "node ID" in each print_widgets report, in order.
std::vector<double> boxHeights(const std::string& out, const std::string& id) {
  std::vector<double> heights;
  for (const std::string& line : test::splitLines(out)) {
    std::string prefix = "widget node " + id + ": ";
    if (line.rfind(prefix, 0) != 0) continue;
    std::istringstream in(line.substr(prefix.size()));
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    in >> x0 >> y0 >> x1 >> y1;
    heights.push_back(y1 - y0);
  }
  return heights;
}

TEST(Authoring, AFunctionNodeShowsThePortsOfItsFileAndFollowsItsSaves) {
  ChainDir c;
  test::writeFile(c.dir + "/fn.glsl", "float fn(float a) { return a; }\n");
  test::writeFile(c.dir + "/three.glsl", "vec3 fn(float a, float b, vec2 c, out float d) { d = a; return vec3(a, b, c.x); }\n");
  test::writeFile(c.dir + "/fn.json", R"({"version": 1, "name": "fn",
    "nodes": [{"id": "uv", "type": "uv", "editor": {"x": 0, "y": 0}},
              {"id": "f", "type": "glsl_function", "options": {"file": "fn.glsl", "function": "fn"},
               "inputs": {"a": 0.5}, "editor": {"x": 300, "y": 0}}],
    "outputs": {"fragment": {"color": [0.5, 0.5, 0.5]}}})");
  test::EditorRun r = c.run(R"([
    {"op": "frames", "count": 1},
    {"op": "print_widgets", "prefix": "node f"},
    {"op": "external_write", "path": ")" + c.dir + R"(/fn.glsl", "from": ")" + c.dir + R"(/three.glsl"},
    {"op": "wait_reload"},
    {"op": "frames", "count": 2},
    {"op": "print_widgets", "prefix": "node f"},
    {"op": "connect", "from": "uv.out", "to": "f.c"}
  ])", c.dir + "/fn.json");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  std::vector<double> h = boxHeights(r.out, "f");
  ASSERT_EQ(h.size(), 2u) << r.out;
  EXPECT_NEAR(h[1] - h[0], 2 * 18, 1) << "one row, then three (a, b, c against out, d)";
}

TEST(Authoring, ThePaletteWritesANewFunctionNodeFromTheTemplate) {
  ChainDir c;
  test::EditorRun r = c.run(R"([
    {"op": "frames", "count": 1},
    {"op": "click", "widget": "canvas", "at": [0.5, 0.9], "button": "right"},
    {"op": "frames", "count": 1},
    {"op": "click", "widget": "new function name"},
    {"op": "type", "text": "wave"},
    {"op": "key", "key": "enter"},
    {"op": "frames", "count": 1},
    {"op": "click", "widget": "new function button"},
    {"op": "frames", "count": 2},
    {"op": "save"}
  ])");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(test::readFile(c.dir + "/wave.glsl"), functionTemplateText("wave"));
  Graph g = c.saved();
  const Node* n = g.findNode("glsl_function_1");
  ASSERT_TRUE(n);
  EXPECT_EQ(writtenOptions(*n), nlohmann::json({{"file", "wave.glsl"}, {"function", "wave"}}));
  EXPECT_EQ(g.nodes.size(), chainGraph().nodes.size() + 1) << "Enter in the name field adds no palette entry";
  auto ports = editorPortsOf(g, defaultRegistry(), *n);
  ASSERT_TRUE(ports);
  EXPECT_EQ(portNames(ports->outputs), (std::vector<std::string>{"out:vec3"}));
}

}  // namespace
}  // namespace wg::editor
