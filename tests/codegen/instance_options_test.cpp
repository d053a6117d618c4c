// Options of a subgraph instance (docs/graph-format.md, "Options of an instance"): a choice
// or a number is a static `$name` inside the function graph, folded like a literal input;
// a texture is sampled by the nodes that write "$name", with the sampler state the
// instance sets; a function graph compiled on its own takes the defaults; `fmt` keeps the
// declarations. The bad inputs are tests/bad/WG090..WG093 (bad_graphs_test).
#include <gtest/gtest.h>

#include <string>

#include "codegen/compile.h"
#include "codegen/cpu_backend.h"
#include "core/graph_io.h"
#include "core/node_preview_graph.h"
#include "nodes/node_docs.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg {
namespace {

// A layer: the debris texture's alpha at uv, shading (look "shadow": 1 - a) or brightening
// (look "glint": a * layers) the light, in a choice and a number fixed per instance.
const char* kOptionsLayer = R"json({
  "version": 1,
  "name": "layer",
  "interface": {
    "options": {
      "debris": {"type": "texture", "default": "builtin:foam"},
      "look": {"type": "choice", "choices": ["shadow", "glint"], "default": "shadow"},
      "layers": {"type": "number", "min": 1, "max": 4, "default": 2}
    },
    "outputs": {"amount": {"type": "float", "source": "shade.out"}, "rgb": {"type": "vec3", "source": "debris.rgb"}}
  },
  "nodes": [
    {"id": "debris", "type": "texture_sample", "options": {"texture": "$debris", "color_space": "linear"}},
    {"id": "shade", "type": "expression",
     "options": {"inputs": {"a": "float", "look": "float", "n": "float"}, "formula": "mix(1.0 - a, a * n, look)"},
     "inputs": {"a": "debris.alpha", "look": "$look", "n": "$layers"}}
  ]
}
)json";

struct OptionsTree : test::FileTree {
  OptionsTree() : FileTree("wg_instance_options") {}
};

struct OptionsBuilt {
  std::optional<CompileResult> result;
  Diagnostics diags;
};

OptionsBuilt buildWithOptions(const std::string& path) {
  OptionsBuilt b;
  auto graph = loadGraphFile(path, b.diags);
  if (graph) b.result = compileGraph(*graph, defaultRegistry(), CompileOptions{}, b.diags);
  return b;
}

// A function graph compiled on its own, shown through its first interface output (as
// compile, render and check show one that connects no output slots).
OptionsBuilt buildOnItsOwn(const std::string& path) {
  OptionsBuilt b;
  auto graph = loadGraphFile(path, b.diags);
  std::string why;
  if (graph) graph = interfaceOutputGraph(*graph, &why);
  if (graph) b.result = compileGraph(*graph, defaultRegistry(), CompileOptions{}, b.diags);
  return b;
}

std::string optionsDiagText(const Diagnostics& d) {
  std::string s;
  for (const auto& x : d.sorted()) s += formatText(x) + "\n";
  return s;
}

std::string optionsFragment(const CompileResult& r) {
  for (const auto& f : r.files)
    if (f.name.ends_with(".glsl330.frag")) return f.contents;
  return "";
}

// A graph of two instances `a` and `b` with the options given (JSON members, may be empty),
// their amounts side by side in the colour.
std::string twoInstances(const std::string& aOptions, const std::string& bOptions) {
  return R"({
  "version": 1, "name": "canal",
  "imports": {"layer": "lib/layer.json"},
  "nodes": [
    {"id": "a", "type": "layer", "options": {)" + aOptions + R"(}},
    {"id": "b", "type": "layer", "options": {)" + bOptions + R"(}},
    {"id": "c", "type": "combine", "options": {"type": "vec3"}, "inputs": {"x": "a.amount", "y": "b.amount", "z": 0}}
  ],
  "outputs": {"fragment": {"color": "c.out"}}
})";
}

const Op* opNamed(const Program& p, const std::string& id) {
  for (const auto& op : p.ops)
    if (op.nodeId == id) return &op;
  return nullptr;
}

std::string textureOf(const Program& p, const std::string& id) {
  const Op* op = opNamed(p, id);
  return op ? op->sharedOptions->at("texture").get<std::string>() : "";
}

TEST(InstanceOptions, AChoiceIsStaticAndEachInstanceCompilesOnlyItsSide) {
  OptionsTree tree;
  tree.write("lib/layer.json", kOptionsLayer);
  OptionsBuilt b = buildWithOptions(tree.write("canal.json", twoInstances(R"("look": "shadow")", R"("look": "glint", "layers": 3)")));
  ASSERT_TRUE(b.result) << optionsDiagText(b.diags);
  // Each mix reduced to the side its instance chose: `a` computes 1 - alpha, `b` alpha * 3,
  // and neither computes the other's side.
  std::string frag = optionsFragment(*b.result);
  EXPECT_EQ(frag.find("mix("), std::string::npos) << frag;
  EXPECT_NE(frag.find("(1.0 - n0_a_debris_alpha)"), std::string::npos) << frag;
  EXPECT_NE(frag.find("(n0_a_debris_alpha * 3.0)"), std::string::npos) << frag;
  EXPECT_EQ(frag.find("* 2.0"), std::string::npos) << frag;
  // On the CPU: the builtin foam texture is opaque, so a = 1 - 1 = 0 and b = 1 * 3.
  EvalEnvironment env;
  env.uv = Value::vector({0.3, 0.6});
  Value c = evaluateProgram(b.result->program, env).outputs.at(0);
  EXPECT_DOUBLE_EQ(c[0], 0.0);
  EXPECT_DOUBLE_EQ(c[1], 3.0);
}

TEST(InstanceOptions, EachInstanceSamplesItsOwnTextureWithItsSamplerState) {
  OptionsTree tree;
  tree.write("lib/layer.json", kOptionsLayer);
  // A PNG beside the canal (not beside the function graph): the instance's path is its own.
  std::string png = test::readFile(test::sourcePath("graphs/lagoon_ripples.png"));
  tree.write("leaves.png", png);
  OptionsBuilt b = buildWithOptions(tree.write(
      "canal.json", twoInstances(R"("debris": "builtin:height")",
                                 R"("debris": {"file": "leaves.png", "wrap": "mirror", "filter": "nearest"})")));
  ASSERT_TRUE(b.result) << optionsDiagText(b.diags);
  EXPECT_EQ(textureOf(b.result->program, "a/debris"), "builtin:height");
  EXPECT_EQ(textureOf(b.result->program, "b/debris"), "leaves.png");
  const Op* a = opNamed(b.result->program, "a/debris");
  const Op* second = opNamed(b.result->program, "b/debris");
  ASSERT_TRUE(a && second);
  EXPECT_EQ(a->sharedOptions->at("wrap"), "repeat");  // the node's own (its default)
  EXPECT_EQ(second->sharedOptions->at("wrap"), "mirror");
  EXPECT_EQ(second->sharedOptions->at("filter"), "nearest");
  EXPECT_EQ(second->sharedOptions->at("color_space"), "linear");  // not set by the instance: the node's
  // Two samplers in the shader, the manifest naming the file and its state.
  std::string manifest;
  for (const auto& f : b.result->files)
    if (f.name.ends_with(".manifest.json")) manifest = f.contents;
  EXPECT_NE(manifest.find("leaves.png"), std::string::npos) << manifest;
  EXPECT_NE(manifest.find("mirror"), std::string::npos) << manifest;
}

TEST(InstanceOptions, DefaultsApplyWhereAnInstanceSetsNothingAndWhenCompiledOnItsOwn) {
  OptionsTree tree;
  tree.write("lib/layer.json", kOptionsLayer);
  OptionsBuilt b = buildWithOptions(tree.write("canal.json", twoInstances("", R"("look": "glint")")));
  ASSERT_TRUE(b.result) << optionsDiagText(b.diags);
  EXPECT_EQ(textureOf(b.result->program, "a/debris"), "builtin:foam");
  EvalEnvironment env;
  env.uv = Value::vector({0.3, 0.6});
  Value c = evaluateProgram(b.result->program, env).outputs.at(0);
  EXPECT_DOUBLE_EQ(c[0], 0.0);  // shadow
  EXPECT_DOUBLE_EQ(c[1], 2.0);  // glint x the default 2 layers
  OptionsBuilt own = buildOnItsOwn(tree.path("lib/layer.json"));
  ASSERT_TRUE(own.result) << optionsDiagText(own.diags);
  EXPECT_EQ(textureOf(own.result->program, "debris"), "builtin:foam");
}

TEST(InstanceOptions, AnOptionWithoutADefaultStopsACompileOnItsOwnAtTheOption) {
  OptionsTree tree;
  std::string lib = kOptionsLayer;
  lib.replace(lib.find(R"(, "default": "shadow")"), std::string(R"(, "default": "shadow")").size(), "");
  OptionsBuilt own = buildOnItsOwn(tree.write("lib/layer.json", lib));
  EXPECT_FALSE(own.result);
  std::string all = optionsDiagText(own.diags);
  EXPECT_NE(all.find("[WG090] option 'look' has no default"), std::string::npos) << all;
  EXPECT_NE(all.find("layer.json:7:7:"), std::string::npos) << all;  // the option's key
}

TEST(InstanceOptions, ErrorsNameTheInstanceAndTheOption) {
  OptionsTree tree;
  tree.write("lib/layer.json", kOptionsLayer);
  struct Case {
    std::string options, code, says;
  };
  for (const Case& c : {
           Case{R"("look": "glow")", "WG092", "instance 'b': option 'look' is 'glow', not one of its choices 'shadow', 'glint'"},
           Case{R"("layers": 0.5)", "WG092", "instance 'b': option 'layers' is 0.5, outside its range [1, 4]"},
           Case{R"("layers": "two")", "WG092", "option 'layers' must be a number"},
           Case{R"("debris": {"file": "x.png", "wrap": "tile"})", "WG092", "option 'debris' has 'wrap' \"tile\""},
           Case{R"("colour": 1)", "WG091", "instance 'b': the interface of 'layer' declares no option 'colour'"},
           Case{R"("debris": "../outside.png")", "WG093", "instance 'b': option 'debris' cannot be used: texture path '../outside.png' leaves"},
           Case{R"("debris": "nothing.png")", "WG093", "does not exist"},
           Case{R"("debris": "builtin:leaves")", "WG093", "unknown built-in texture 'builtin:leaves'"},
       }) {
    OptionsBuilt b = buildWithOptions(tree.write("canal.json", twoInstances("", c.options)));
    EXPECT_FALSE(b.result) << c.options;
    std::string all = optionsDiagText(b.diags);
    EXPECT_NE(all.find("[" + c.code + "] "), std::string::npos) << c.options << "\n" << all;
    EXPECT_NE(all.find(c.says), std::string::npos) << c.options << "\n" << all;
    EXPECT_NE(all.find("canal.json:6:"), std::string::npos) << c.options << "\n" << all;  // b's line
  }
}

TEST(InstanceOptions, AnUndecodablePngIsRefusedAtTheInstance) {
  OptionsTree tree;
  tree.write("lib/layer.json", kOptionsLayer);
  // A valid header over a broken zlib stream: found when resolved, not first by render.
  std::string png = test::readFile(test::sourcePath("graphs/lagoon_ripples.png"));
  png.resize(200);
  tree.write("broken.png", png);
  OptionsBuilt b = buildWithOptions(tree.write("canal.json", twoInstances("", R"("debris": "broken.png")")));
  EXPECT_FALSE(b.result);
  std::string all = optionsDiagText(b.diags);
  EXPECT_NE(all.find("[WG093] instance 'b': option 'debris' cannot be used"), std::string::npos) << all;
}

TEST(InstanceOptions, ANodeReadingAnUndeclaredTextureIsRefused) {
  OptionsTree tree;
  std::string lib = kOptionsLayer;
  lib.replace(lib.find(R"("texture": "$debris")"), std::string(R"("texture": "$debris")").size(), R"("texture": "$leaves")");
  tree.write("lib/layer.json", lib);
  OptionsBuilt b = buildWithOptions(tree.write("canal.json", twoInstances("", "")));
  EXPECT_FALSE(b.result);
  std::string all = optionsDiagText(b.diags);
  EXPECT_NE(all.find("[WG091] option 'texture' reads the interface texture 'leaves'"), std::string::npos) << all;
  EXPECT_NE(all.find("note: in instance 'a'"), std::string::npos) << all;
}

TEST(InstanceOptions, ASamplerStateForANodeWithoutOneIsRefused) {
  OptionsTree tree;
  tree.write("lib/shade.glsl", "float shade(sampler2D t, vec2 uv) { return texture(t, uv).a; }\n");
  tree.write("lib/layer.json", R"({
  "version": 1, "name": "layer",
  "interface": {"options": {"debris": {"type": "texture", "default": "builtin:foam"}},
                "outputs": {"amount": {"type": "float", "source": "f.out"}}},
  "nodes": [{"id": "uv", "type": "uv"},
            {"id": "f", "type": "glsl_function", "options": {"file": "shade.glsl", "function": "shade", "t": "$debris"},
             "inputs": {"uv": "uv.out"}}]
})");
  OptionsBuilt plain = buildWithOptions(tree.write("canal.json", twoInstances("", R"("debris": "builtin:height")")));
  ASSERT_TRUE(plain.result) << optionsDiagText(plain.diags);
  const Op* f = opNamed(plain.result->program, "b/f");
  ASSERT_TRUE(f);
  EXPECT_EQ(f->sharedOptions->at("t"), "builtin:height");
  OptionsBuilt b = buildWithOptions(tree.write("canal.json", twoInstances("", R"("debris": {"file": "builtin:height", "wrap": "clamp"})")));
  EXPECT_FALSE(b.result);
  std::string all = optionsDiagText(b.diags);
  EXPECT_NE(all.find("[WG092] the texture 'debris' sets 'wrap', but node 'b/f' (glsl_function)"), std::string::npos) << all;
}

TEST(InstanceOptions, APresetSetsAnInstancesOptionAndEveryPresetIsChecked) {
  OptionsTree tree;
  tree.write("lib/layer.json", kOptionsLayer);
  std::string graph = twoInstances("", "");
  graph.replace(graph.find(R"("nodes")"), 7, R"("presets": {"bright": {"a.look": "glint", "a.layers": 4}}, "nodes")");
  std::string path = tree.write("canal.json", graph);
  Diagnostics d;
  auto g = loadGraphFile(path, d);
  ASSERT_TRUE(g) << optionsDiagText(d);
  CompileOptions options;
  options.preset = "bright";
  auto r = compileGraph(*g, defaultRegistry(), options, d);
  ASSERT_TRUE(r) << optionsDiagText(d);
  EvalEnvironment env;
  env.uv = Value::vector({0.3, 0.6});
  Value c = evaluateProgram(r->program, env).outputs.at(0);
  EXPECT_DOUBLE_EQ(c[0], 4.0);  // glint x 4 layers
  EXPECT_DOUBLE_EQ(c[1], 0.0);  // b: shadow, as declared

  graph.replace(graph.find(R"("a.layers": 4)"), 13, R"("a.layers": 5)");
  OptionsBuilt b = buildWithOptions(tree.write("canal.json", graph));  // no preset applied: still checked
  EXPECT_FALSE(b.result);
  EXPECT_NE(optionsDiagText(b.diags).find("[WG092] preset 'bright': option 'layers' is 5, outside its range [1, 4]"),
            std::string::npos)
      << optionsDiagText(b.diags);
}

TEST(InstanceOptions, TheNodeTypeListsItsOptions) {
  OptionsTree tree;
  Diagnostics d;
  auto g = loadGraphFile(tree.write("lib/layer.json", kOptionsLayer), d);
  ASSERT_TRUE(g) << optionsDiagText(d);
  std::string shown = functionGraphText("layer", *g);
  EXPECT_NE(shown.find("  options (fixed per instance):\n"
                       "    debris: texture, default \"builtin:foam\"\n"
                       "    look: choice [\"shadow\",\"glint\"], default \"shadow\"\n"
                       "    layers: number in [1, 4], default 2\n"),
            std::string::npos)
      << shown;
  EXPECT_EQ(functionGraphJson("layer", *g)["options"][1]["choices"], (nlohmann::json{"shadow", "glint"}));
}

TEST(InstanceOptions, AnOptionMayNotShareAParametersName) {
  OptionsTree tree;
  std::string lib = kOptionsLayer;
  lib.replace(lib.find(R"("nodes")"), 7, R"("parameters": {"look": {"type": "float", "default": 0}}, "nodes")");
  OptionsBuilt b = buildWithOptions(tree.write("lib/layer.json", lib));
  EXPECT_FALSE(b.result);
  EXPECT_NE(optionsDiagText(b.diags).find("[WG011] interface option 'look' has the name of a parameter"), std::string::npos)
      << optionsDiagText(b.diags);
}

TEST(InstanceOptions, FmtKeepsTheDeclarationsAndTheInstancesOptions) {
  OptionsTree tree;
  tree.write("lib/layer.json", kOptionsLayer);
  for (const std::string& path : {tree.path("lib/layer.json"),
                                  tree.write("canal.json", twoInstances(R"("look": "glint")",
                                                                        R"("debris": {"file": "builtin:height", "wrap": "mirror"})"))}) {
    Diagnostics d;
    auto g = loadGraphFile(path, d);
    ASSERT_TRUE(g) << optionsDiagText(d);
    std::string saved = saveGraph(*g);
    std::string again = tree.write("again.json", saved);
    Diagnostics d2;
    auto g2 = loadGraphFile(again, d2);
    ASSERT_TRUE(g2) << optionsDiagText(d2) << saved;
    EXPECT_EQ(saveGraph(*g2), saved);
    if (g->interface) {
      ASSERT_EQ(g2->interface->options.size(), 3u) << saved;
      EXPECT_EQ(g2->interface->options[1].choices, (std::vector<std::string>{"shadow", "glint"}));
      EXPECT_EQ(g2->interface->options[2].max, 4.0);
      EXPECT_EQ(g2->interface->options[0].defaultValue, "builtin:foam");
    }
  }
}

}  // namespace
}  // namespace wg

namespace wg {
namespace {

// The WGSL checks take the example graphs without a glsl_function node, found in the graph
// or any subgraph it imports (test::holdsGlslFunction), not by name.
TEST(ExampleGraphs, GlslFunctionNodesAreFoundThroughSubgraphs) {
  EXPECT_TRUE(test::holdsGlslFunction(test::sourcePath("graphs/caustic_pool.json")));  // in lib/caustic_light.json
  EXPECT_TRUE(test::holdsGlslFunction(test::sourcePath("graphs/lib/caustic_light.json")));
  EXPECT_FALSE(test::holdsGlslFunction(test::sourcePath("graphs/lake.json")));
  EXPECT_FALSE(test::holdsGlslFunction(test::sourcePath("graphs/pool.json")));  // subgraphs without one
}

}  // namespace
}  // namespace wg
