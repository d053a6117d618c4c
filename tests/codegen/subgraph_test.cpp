// Subgraphs (docs/graph-format.md, "Subgraphs"): function graphs imported as node types are
// inlined into the program before the passes, so the result is the program of the same
// nodes written out by hand; every fault inside one is reported in its file with a note
// per instance; the import rules (paths, cycles, depth, inlined size) are diagnostics.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "codegen/compile.h"
#include "codegen/cpu_backend.h"
#include "core/graph_imports.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg {
namespace {

namespace fs = std::filesystem;

// A folder of the test's files (test::FileTree), removed afterwards.
struct GraphTree : test::FileTree {
  GraphTree() : FileTree("wg_subgraph") {}
};

// A function graph: colour = mix(water, sky, fresnel(f0)) with its parameters as inputs.
const char* kSkyBlend = R"({
  "version": 1,
  "name": "sky_blend",
  "interface": {
    "description": "water blended towards the sky by Fresnel-Schlick",
    "outputs": {"color": {"type": "vec3", "source": "blend.out"},
                "reflectance": {"type": "float", "source": "fresnel.reflectance"}}
  },
  "parameters": {
    "water": {"type": "vec3", "default": [0, 0.3, 0.4], "min": 0, "max": 1},
    "f0": {"type": "float", "default": 0.02, "min": 0, "max": 1}
  },
  "nodes": [
    {"id": "fresnel", "type": "fresnel", "options": {"model": "schlick"}, "inputs": {"f0": "$f0"}},
    {"id": "blend", "type": "mix", "inputs": {"a": "$water", "b": [0.55, 0.7, 0.9], "t": "fresnel.reflectance"}}
  ]
}
)";

// A parent with two instances: `a` from a parameter, `b` from a literal water colour and f0.
const char* kTwoInstances = R"({
  "version": 1,
  "name": "parent",
  "imports": {"sky_blend": "lib/sky_blend.json"},
  "parameters": {"deep": {"type": "vec3", "default": [0, 0.1, 0.3], "min": 0, "max": 1}},
  "nodes": [
    {"id": "a", "type": "sky_blend", "inputs": {"water": "$deep"}},
    {"id": "b", "type": "sky_blend", "inputs": {"water": [0.2, 0.2, 0.2], "f0": 0.5}},
    {"id": "sum", "type": "add", "inputs": {"a": "a.color", "b": "b.color"}}
  ],
  "outputs": {"fragment": {"color": "sum.out"}}
}
)";

// The same program with the nodes written out by hand.
const char* kWrittenOut = R"({
  "version": 1,
  "name": "parent",
  "parameters": {"deep": {"type": "vec3", "default": [0, 0.1, 0.3], "min": 0, "max": 1}},
  "nodes": [
    {"id": "fa", "type": "fresnel", "options": {"model": "schlick"}, "inputs": {"f0": 0.02}},
    {"id": "ma", "type": "mix", "inputs": {"a": "$deep", "b": [0.55, 0.7, 0.9], "t": "fa.reflectance"}},
    {"id": "fb", "type": "fresnel", "options": {"model": "schlick"}, "inputs": {"f0": 0.5}},
    {"id": "mb", "type": "mix", "inputs": {"a": [0.2, 0.2, 0.2], "b": [0.55, 0.7, 0.9], "t": "fb.reflectance"}},
    {"id": "sum", "type": "add", "inputs": {"a": "ma.out", "b": "mb.out"}}
  ],
  "outputs": {"fragment": {"color": "sum.out"}}
}
)";

struct Built {
  std::optional<CompileResult> result;
  Diagnostics diags;
};

Built compileTree(const std::string& path) {
  Built b;
  auto graph = loadGraphFile(path, b.diags);
  if (graph) b.result = compileGraph(*graph, defaultRegistry(), CompileOptions{}, b.diags);
  return b;
}

std::string diagnosticsText(const Diagnostics& d) {
  std::string s;
  for (const auto& x : d.sorted()) s += formatText(x) + "\n";
  return s;
}

std::string glslFragment(const CompileResult& r) {
  for (const auto& f : r.files)
    if (f.name.ends_with(".glsl330.frag")) return f.contents;
  return "";
}

// The program's colour output on the CPU, for a view at `cosine` to an upward normal.
Value colourAt(const Program& p, double cosine) {
  EvalEnvironment env;
  double s = std::sqrt(1 - cosine * cosine);
  env.viewDirection = Value::vector({s, cosine, 0});
  env.normal = Value::vector({0, 1, 0});
  return evaluateProgram(p, env).outputs.at(0);
}

TEST(Subgraph, TwoInstancesWithDifferentInputsComputeWhatTheWrittenOutNodesCompute) {
  GraphTree tree;
  tree.write("lib/sky_blend.json", kSkyBlend);
  Built inlined = compileTree(tree.write("parent.json", kTwoInstances));
  Built written = compileTree(tree.write("written.json", kWrittenOut));
  ASSERT_TRUE(inlined.result) << diagnosticsText(inlined.diags);
  ASSERT_TRUE(written.result) << diagnosticsText(written.diags);
  EXPECT_EQ(inlined.result->nodesKept, written.result->nodesKept);
  EXPECT_EQ(inlined.result->nodesTotal, 5);  // two instances of two nodes, and `sum`
  for (double c : {1.0, 0.7, 0.2, 1e-3}) {
    Value x = colourAt(inlined.result->program, c), y = colourAt(written.result->program, c);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(x[k], y[k]) << "cos " << c << " component " << k;
  }
  // Ids inside an instance are prefixed with it; the literal f0 of `b` folded into its call.
  std::string frag = glslFragment(*inlined.result);
  EXPECT_NE(frag.find("_b_fresnel"), std::string::npos) << frag;
  EXPECT_NE(frag.find("wg_fresnel_schlick(n"), std::string::npos);
  EXPECT_NE(frag.find(", 0.5)"), std::string::npos) << frag;
  EXPECT_EQ(inlined.result->manifest.imports, std::vector<std::string>{"lib/sky_blend.json"});
}

TEST(Subgraph, TwoInstancesFedTheSameValuesBecomeOne) {
  GraphTree tree;
  tree.write("lib/sky_blend.json", kSkyBlend);
  Built b = compileTree(tree.write("parent.json", R"({
  "version": 1, "name": "same",
  "imports": {"sky_blend": "lib/sky_blend.json"},
  "parameters": {"deep": {"type": "vec3", "default": [0, 0.1, 0.3], "min": 0, "max": 1}},
  "nodes": [
    {"id": "a", "type": "sky_blend", "inputs": {"water": "$deep"}},
    {"id": "b", "type": "sky_blend", "inputs": {"water": "$deep"}},
    {"id": "sum", "type": "add", "inputs": {"a": "a.color", "b": "b.color"}}
  ],
  "outputs": {"fragment": {"color": "sum.out"}}
})"));
  ASSERT_TRUE(b.result) << diagnosticsText(b.diags);
  EXPECT_EQ(b.result->nodesKept, 3);  // fresnel, mix, add: b's two nodes merged into a's
  bool merged = false;
  for (const auto& r : b.result->program.removed) merged |= r.what == "b/blend" && r.reason.find("a/blend") != std::string::npos;
  EXPECT_TRUE(merged);
}

TEST(Subgraph, AnOutputNobodyReadsIsNotComputed) {
  GraphTree tree;
  tree.write("lib/sky_blend.json", kSkyBlend);
  Built b = compileTree(tree.write("parent.json", R"({
  "version": 1, "name": "only_reflectance",
  "imports": {"sky_blend": "lib/sky_blend.json"},
  "nodes": [{"id": "a", "type": "sky_blend"}],
  "outputs": {"fragment": {"color": "a.reflectance"}}
})"));
  ASSERT_TRUE(b.result) << diagnosticsText(b.diags);
  EXPECT_EQ(b.result->nodesKept, 1);  // the fresnel alone; the blend is pruned
}

// Four files, each wrapping the next: level1 -> level2 -> level3 -> level4 -> sky_blend.
TEST(Subgraph, SubgraphsUsingSubgraphsFourLevelsDeep) {
  GraphTree tree;
  tree.write("lib/sky_blend.json", kSkyBlend);
  std::string next = "sky_blend.json", nextType = "sky_blend";
  for (int level = 4; level >= 1; --level) {
    std::string name = "level" + std::to_string(level);
    tree.write("lib/" + name + ".json", R"({
  "version": 1, "name": ")" + name + R"(",
  "imports": {")" + nextType + R"(": ")" + next + R"("},
  "interface": {"outputs": {"color": {"type": "vec3", "source": "inner.color"}}},
  "parameters": {"f0": {"type": "float", "default": 0.02, "min": 0, "max": 1}},
  "nodes": [{"id": "inner", "type": ")" + nextType + R"(", "inputs": {"f0": "$f0"}}]
})");
    next = name + ".json";
    nextType = name;
  }
  Built b = compileTree(tree.write("parent.json", R"({
  "version": 1, "name": "deep",
  "imports": {"level1": "lib/level1.json"},
  "nodes": [{"id": "top", "type": "level1", "inputs": {"f0": 0.5}}],
  "outputs": {"fragment": {"color": "top.color"}}
})"));
  ASSERT_TRUE(b.result) << diagnosticsText(b.diags);
  bool found = false;
  for (const auto& op : b.result->program.ops) found |= op.nodeId == "top/inner/inner/inner/inner/fresnel";
  EXPECT_TRUE(found);
  EXPECT_EQ(b.result->manifest.imports.size(), 5u);
  EXPECT_NE(glslFragment(*b.result).find(", 0.5)"), std::string::npos);  // the literal reached the innermost node
}

TEST(Subgraph, AFileImportedThroughTwoPathsIsLoadedOnce) {
  GraphTree tree;
  tree.write("lib/sky_blend.json", kSkyBlend);
  for (const char* name : {"left", "right"})
    tree.write(std::string("lib/") + name + ".json", std::string(R"({
  "version": 1, "name": ")") + name + R"(",
  "imports": {"sky": "sky_blend.json"},
  "interface": {"outputs": {"color": {"type": "vec3", "source": "s.color"}}},
  "nodes": [{"id": "s", "type": "sky"}]
})");
  Diagnostics diags;
  auto g = loadGraphFile(tree.write("parent.json", R"({
  "version": 1, "name": "diamond",
  "imports": {"left": "lib/left.json", "right": "lib/right.json", "again": "lib/sky_blend.json"},
  "nodes": [{"id": "l", "type": "left"}, {"id": "r", "type": "right"},
            {"id": "sum", "type": "add", "inputs": {"a": "l.color", "b": "r.color"}}],
  "outputs": {"fragment": {"color": "sum.out"}}
})"),
                         diags);
  ASSERT_TRUE(g) << diagnosticsText(diags);
  const Graph* viaLeft = g->imports[0].graph->imports[0].graph.get();
  const Graph* viaRight = g->imports[1].graph->imports[0].graph.get();
  EXPECT_EQ(viaLeft, viaRight);
  EXPECT_EQ(viaLeft, g->imports[2].graph.get());
  EXPECT_EQ(graphFilesRead(*g).size(), 4u);  // parent, left, right, sky_blend
  // One file under two names ("sky" in left and right, "again" here) is a node type under each.
  auto r = compileGraph(*g, defaultRegistry(), CompileOptions{}, diags);
  ASSERT_TRUE(r) << diagnosticsText(diags);
  EXPECT_EQ(r->nodesKept, 3);  // l/s and r/s are the same computation: one fresnel, one mix, the add
}

TEST(Subgraph, AFaultInsideASubgraphPointsIntoItsFileWithANotePerInstance) {
  GraphTree tree;
  std::string broken = kSkyBlend;
  broken.replace(broken.find("\"t\": \"fresnel.reflectance\""), 26, "\"t\": \"fresnel.reflectanc\"");
  std::string lib = tree.write("lib/sky_blend.json", broken);
  std::string parent = tree.write("parent.json", kTwoInstances);
  Built b = compileTree(parent);
  ASSERT_FALSE(b.result);
  auto sorted = b.diags.sorted();
  ASSERT_EQ(sorted.size(), 2u) << diagnosticsText(b.diags);  // once per instance
  for (size_t i = 0; i < 2; ++i) {
    const Diagnostic& d = sorted[i];
    EXPECT_EQ(d.code, DiagCode::UnknownOutputPort);
    EXPECT_EQ(d.where.file, lib);
    EXPECT_EQ(d.where.line, 15);  // the blend node's "t": the value's quote
    EXPECT_EQ(d.where.col, 90);
    ASSERT_EQ(d.locatedNotes.size(), 1u);
    EXPECT_EQ(d.locatedNotes[0].where.file, parent);
    EXPECT_EQ(d.locatedNotes[0].where.line, i == 0 ? 7 : 8);
    EXPECT_EQ(d.locatedNotes[0].where.col, 5);
  }
  std::string text = formatText(sorted[0]);
  EXPECT_NE(text.find("\n" + parent + ":7:5: note: in instance 'a' of 'lib/sky_blend.json'"), std::string::npos) << text;
  nlohmann::json j = toJson(sorted[0]);
  EXPECT_EQ(j["located_notes"][0]["line"], 7);
  EXPECT_EQ(j["located_notes"][0]["message"], "in instance 'a' of 'lib/sky_blend.json'");
}

TEST(Subgraph, NestedInstancesAreNamedInnermostFirst) {
  GraphTree tree;
  tree.write("lib/leaf.json", R"({
  "version": 1, "name": "leaf",
  "interface": {"outputs": {"v": {"type": "float", "source": "n.out"}}},
  "nodes": [{"id": "n", "type": "saturate", "inputs": {"x": "missing.out"}}]
})");
  tree.write("lib/middle.json", R"({
  "version": 1, "name": "middle",
  "imports": {"leaf": "leaf.json"},
  "interface": {"outputs": {"v": {"type": "float", "source": "inner.v"}}},
  "nodes": [{"id": "inner", "type": "leaf"}]
})");
  Built b = compileTree(tree.write("parent.json", R"({
  "version": 1, "name": "p",
  "imports": {"middle": "lib/middle.json"},
  "nodes": [{"id": "outer", "type": "middle"}],
  "outputs": {"fragment": {"alpha": "outer.v"}}
})"));
  ASSERT_FALSE(b.result);
  auto sorted = b.diags.sorted();
  ASSERT_FALSE(sorted.empty());
  const Diagnostic& d = sorted[0];
  EXPECT_EQ(d.code, DiagCode::DanglingReference);
  EXPECT_EQ(d.where.file, tree.path("lib/leaf.json"));
  ASSERT_EQ(d.locatedNotes.size(), 2u) << diagnosticsText(b.diags);
  EXPECT_EQ(d.locatedNotes[0].message, "in instance 'outer/inner' of 'leaf.json'");
  EXPECT_EQ(d.locatedNotes[0].where.file, tree.path("lib/middle.json"));
  EXPECT_EQ(d.locatedNotes[1].message, "in instance 'outer' of 'lib/middle.json'");
  EXPECT_EQ(d.locatedNotes[1].where.file, tree.path("parent.json"));
}

// A fault found after resolve (the stage pass) names the op's instances too.
TEST(Subgraph, AStageFaultInsideASubgraphCarriesTheInstanceNote) {
  GraphTree tree;
  tree.write("lib/screen.json", R"({
  "version": 1, "name": "screen",
  "interface": {"outputs": {"u": {"type": "float", "source": "u.out"}}},
  "nodes": [{"id": "s", "type": "screen_uv"}, {"id": "u", "type": "swizzle", "options": {"mask": "x"}, "inputs": {"x": "s.out"}}]
})");
  Built b = compileTree(tree.write("parent.json", R"({
  "version": 1, "name": "p",
  "imports": {"screen": "lib/screen.json"},
  "nodes": [{"id": "here", "type": "screen"},
            {"id": "pos", "type": "combine", "options": {"type": "vec3"}, "inputs": {"x": "here.u"}}],
  "outputs": {"vertex": {"position": "pos.out"}}
})"));
  ASSERT_FALSE(b.result);
  auto sorted = b.diags.sorted();
  ASSERT_FALSE(sorted.empty());
  EXPECT_EQ(sorted[0].code, DiagCode::StageMismatch) << diagnosticsText(b.diags);
  EXPECT_EQ(sorted[0].where.file, tree.path("lib/screen.json"));
  ASSERT_EQ(sorted[0].locatedNotes.size(), 1u);
  EXPECT_EQ(sorted[0].locatedNotes[0].message, "in instance 'here' of 'lib/screen.json'");
}

// glslang's messages about a line of generated code map back to the node in the subgraph's
// file, with the instance that put it there (a compiler bug, so the message is made up here).
TEST(Subgraph, AGlslangMessageAboutInlinedCodeNamesTheInstance) {
  GraphTree tree;
  tree.write("lib/sky_blend.json", kSkyBlend);
  Diagnostics diags;
  auto g = loadGraphFile(tree.write("parent.json", kTwoInstances), diags);
  ASSERT_TRUE(g) << diagnosticsText(diags);
  auto program = buildProgram(*g, defaultRegistry(), diags);
  ASSERT_TRUE(program) << diagnosticsText(diags);
  EmitResult er = emitPrograms(*program, {Target::Glsl330}, "parent.json").at(0);
  int line = -1;
  for (size_t i = 0; i < er.shaders[1].lineOp.size() && line < 0; ++i) {
    int op = er.shaders[1].lineOp[i];
    if (op >= 0 && program->ops[static_cast<size_t>(op)].nodeId == "b/blend") line = static_cast<int>(i) + 1;
  }
  ASSERT_GT(line, 0);
  std::vector<ShaderSource> sources{{er.shaders[0].stage, "p.vert", ""}, {er.shaders[1].stage, "p.frag", ""}};
  ValidationResult vr;
  vr.errors.push_back({"p.frag", line, "'x' : undeclared identifier"});
  Diagnostics reported;
  reportRejectedShaders(vr, er.shaders, sources, *program, DiagCode::GlslRejected, reported);
  ASSERT_EQ(reported.all().size(), 1u);
  const Diagnostic& d = reported.all()[0];
  EXPECT_EQ(d.where.file, tree.path("lib/sky_blend.json"));
  EXPECT_EQ(d.where.line, 15);  // the blend node
  EXPECT_EQ(d.node, "b/blend");
  ASSERT_EQ(d.locatedNotes.size(), 1u);
  EXPECT_EQ(d.locatedNotes[0].message, "in instance 'b' of 'lib/sky_blend.json'");
  EXPECT_EQ(d.locatedNotes[0].where.line, 8);
}

TEST(Subgraph, InstanceInputsAreTypeCheckedAndLiteralsRangeChecked) {
  GraphTree tree;
  tree.write("lib/sky_blend.json", kSkyBlend);
  Built wrongType = compileTree(tree.write("t.json", R"({
  "version": 1, "name": "t",
  "imports": {"sky_blend": "lib/sky_blend.json"},
  "nodes": [{"id": "a", "type": "sky_blend", "inputs": {"water": [0.1, 0.2]}}],
  "outputs": {"fragment": {"color": "a.color"}}
})"));
  ASSERT_FALSE(wrongType.result);
  EXPECT_EQ(wrongType.diags.sorted().at(0).code, DiagCode::TypeMismatch) << diagnosticsText(wrongType.diags);
  EXPECT_NE(diagnosticsText(wrongType.diags).find("input 'water' expects vec3, but the literal is vec2"), std::string::npos);

  Built outOfRange = compileTree(tree.write("r.json", R"({
  "version": 1, "name": "r",
  "imports": {"sky_blend": "lib/sky_blend.json"},
  "nodes": [{"id": "a", "type": "sky_blend", "inputs": {"f0": 1.5}}],
  "outputs": {"fragment": {"color": "a.color"}}
})"));
  ASSERT_FALSE(outOfRange.result);
  const std::vector<Diagnostic> sorted = outOfRange.diags.sorted();
  const Diagnostic& d = sorted.at(0);
  EXPECT_EQ(d.code, DiagCode::InterfaceMismatch);
  EXPECT_EQ(d.where.line, 4);
  EXPECT_EQ(d.where.col, 63);
  EXPECT_NE(d.message.find("outside its range [0, 1]"), std::string::npos) << d.message;

  // A float splats to the vec3 input, as it does into any vec3 port.
  Built splat = compileTree(tree.write("s.json", R"({
  "version": 1, "name": "s",
  "imports": {"sky_blend": "lib/sky_blend.json"},
  "nodes": [{"id": "a", "type": "sky_blend", "inputs": {"water": 0.25}}],
  "outputs": {"fragment": {"color": "a.color"}}
})"));
  EXPECT_TRUE(splat.result) << diagnosticsText(splat.diags);
}

TEST(Subgraph, AnInterfaceOutputMustHaveItsDeclaredType) {
  GraphTree tree;
  std::string lib = tree.write("lib/wrong.json", R"({
  "version": 1, "name": "wrong",
  "interface": {"outputs": {"v": {"type": "vec3", "source": "n.out"}}},
  "nodes": [{"id": "n", "type": "saturate", "inputs": {"x": 0.5}}],
  "outputs": {"fragment": {"alpha": "n.out"}}
})");
  // On its own (the interface is checked when the function graph is compiled alone) ...
  Built alone = compileTree(lib);
  ASSERT_FALSE(alone.result);
  EXPECT_EQ(alone.diags.sorted().at(0).code, DiagCode::InterfaceMismatch) << diagnosticsText(alone.diags);
  EXPECT_EQ(alone.diags.sorted().at(0).where.line, 3);
  EXPECT_EQ(alone.diags.sorted().at(0).where.col, 61);
  // ... and through an instance.
  Built used = compileTree(tree.write("p.json", R"({
  "version": 1, "name": "p",
  "imports": {"wrong": "lib/wrong.json"},
  "nodes": [{"id": "w", "type": "wrong"}],
  "outputs": {"fragment": {"color": "w.v"}}
})"));
  ASSERT_FALSE(used.result);
  EXPECT_NE(diagnosticsText(used.diags).find("interface output 'v' is declared vec3, but 'n.out' is float"),
            std::string::npos)
      << diagnosticsText(used.diags);
}

TEST(Subgraph, ImportRulesAreDiagnostics) {
  GraphTree tree;
  tree.write("lib/sky_blend.json", kSkyBlend);
  tree.write("lib/plain.json", R"({"version": 1, "name": "plain", "nodes": [], "outputs": {}})");
  auto firstOf = [&](const std::string& imports) {
    Diagnostics diags;
    std::string path = tree.write("p.json", R"({"version": 1, "name": "p", "imports": )" + imports +
                                                R"(, "nodes": [], "outputs": {"fragment": {"alpha": 1}}})");
    auto g = loadGraphFile(path, diags);
    std::optional<CompileResult> r;
    if (g) r = compileGraph(*g, defaultRegistry(), CompileOptions{}, diags);
    EXPECT_FALSE(r) << imports;
    return diags.sorted().empty() ? Diagnostic{} : diags.sorted()[0];
  };
  EXPECT_EQ(firstOf(R"({"x": "lib/nope.json"})").code, DiagCode::ImportMissing);
  EXPECT_EQ(firstOf(R"({"x": "/etc/hostname"})").code, DiagCode::ImportOutsideTree);
  EXPECT_EQ(firstOf(R"({"x": "../outside.json"})").code, DiagCode::ImportMissing);  // not there at all
  EXPECT_EQ(firstOf(R"({"x": "lib/plain.json"})").code, DiagCode::NotAFunctionGraph);
  EXPECT_EQ(firstOf(R"({"mix": "lib/sky_blend.json"})").code, DiagCode::ImportShadowsNode);
  EXPECT_EQ(firstOf(R"({"x": "lib/sky_blend.json\u0001"})").code, DiagCode::ImportOutsideTree);
  // A file that exists outside the top-level graph's folder, reached by "..".
  GraphTree outer;
  outer.write("outside.json", kSkyBlend);
  std::string inside = outer.write("top/p.json", R"({"version": 1, "name": "p", "imports": {"x": "../outside.json"},
    "nodes": [], "outputs": {"fragment": {"alpha": 1}}})");
  Diagnostics diags;
  EXPECT_FALSE(loadGraphFile(inside, diags));
  EXPECT_EQ(diags.sorted().at(0).code, DiagCode::ImportOutsideTree) << diagnosticsText(diags);
  // ".." that stays inside is fine: lib/a.json imports ../lib/sky_blend.json.
  tree.write("lib/a.json", R"({"version": 1, "name": "a", "imports": {"s": "../lib/sky_blend.json"},
    "interface": {"outputs": {"c": {"type": "vec3", "source": "i.color"}}}, "nodes": [{"id": "i", "type": "s"}]})");
  Built ok = compileTree(tree.write("q.json", R"({"version": 1, "name": "q", "imports": {"a": "lib/a.json"},
    "nodes": [{"id": "x", "type": "a"}], "outputs": {"fragment": {"color": "x.c"}}})"));
  EXPECT_TRUE(ok.result) << diagnosticsText(ok.diags);
}

TEST(Subgraph, AnImportCycleIsOneErrorNamingTheChainOfFiles) {
  GraphTree tree;
  tree.write("lib/a.json", R"({"version": 1, "name": "a", "imports": {"b": "b.json"},
    "interface": {"outputs": {"v": {"type": "float", "source": "x.v"}}}, "nodes": [{"id": "x", "type": "b"}]})");
  tree.write("lib/b.json", R"({"version": 1, "name": "b", "imports": {"a": "a.json"},
    "interface": {"outputs": {"v": {"type": "float", "source": "x.v"}}}, "nodes": [{"id": "x", "type": "a"}]})");
  Diagnostics diags;
  std::string top = tree.write("p.json", R"({"version": 1, "name": "p", "imports": {"a": "lib/a.json"},
    "nodes": [{"id": "x", "type": "a"}], "outputs": {"fragment": {"alpha": "x.v"}}})");
  EXPECT_FALSE(loadGraphFile(top, diags));
  auto sorted = diags.sorted();
  ASSERT_EQ(sorted.size(), 1u) << diagnosticsText(diags);
  EXPECT_EQ(sorted[0].code, DiagCode::ImportCycle);
  EXPECT_EQ(sorted[0].where.file, tree.path("lib/b.json"));
  EXPECT_NE(sorted[0].message.find("'" + tree.path("lib/a.json") + "' -> '" + tree.path("lib/b.json") + "' -> '" +
                                   tree.path("lib/a.json") + "'"),
            std::string::npos)
      << sorted[0].message;
  EXPECT_EQ(sorted[0].locatedNotes.size(), 2u);  // imported as 'b' from a.json, imported as 'a' from p.json
}

// level_1 imports level_2 ... : a chain of `levels` files below the top-level graph.
void writeChain(const GraphTree& tree, int levels) {
  for (int i = 1; i <= levels; ++i) {
    std::string imports = i < levels ? R"("imports": {"next": "level_)" + std::to_string(i + 1) + R"(.json"},)" : "";
    std::string node = i < levels ? R"({"id": "n", "type": "next"})" : R"({"id": "n", "type": "saturate", "inputs": {"x": 0.5}})";
    std::string source = i < levels ? "n.v" : "n.out";
    tree.write("lib/level_" + std::to_string(i) + ".json",
               R"({"version": 1, "name": "l", )" + imports +
                   R"( "interface": {"outputs": {"v": {"type": "float", "source": ")" + source + R"("}}}, "nodes": [)" +
                   node + "]}");
  }
}

TEST(Subgraph, ImportChainsAreLimitedTo16) {
  for (int levels : {16, 17}) {
    GraphTree tree;
    writeChain(tree, levels);
    Built b = compileTree(tree.write("p.json", R"({"version": 1, "name": "p", "imports": {"l": "lib/level_1.json"},
      "nodes": [{"id": "x", "type": "l"}], "outputs": {"fragment": {"alpha": "x.v"}}})"));
    if (levels == 16) {
      EXPECT_TRUE(b.result) << diagnosticsText(b.diags);
    } else {
      ASSERT_FALSE(b.result);
      EXPECT_EQ(b.diags.sorted().at(0).code, DiagCode::ImportTooDeep) << diagnosticsText(b.diags);
    }
  }
}

TEST(Subgraph, TheNodeLimitCountsInlinedNodes) {
  // 20 instances of 20 instances of ... (four levels) of a two-node leaf: 320,000 nodes.
  GraphTree tree;
  tree.write("lib/fan_4.json", R"({"version": 1, "name": "f", "interface": {"outputs": {"v": {"type": "float", "source": "b.out"}}},
    "nodes": [{"id": "a", "type": "saturate", "inputs": {"x": 0.5}}, {"id": "b", "type": "saturate", "inputs": {"x": "a.out"}}]})");
  for (int level = 3; level >= 0; --level) {
    std::string nodes;
    for (int i = 0; i < 20; ++i) nodes += std::string(i ? "," : "") + R"({"id": "i)" + std::to_string(i) + R"(", "type": "next"})";
    std::string head = level == 0 ? R"({"version": 1, "name": "p", "outputs": {"fragment": {"alpha": "i0.v"}},)"
                                  : R"({"version": 1, "name": "f", "interface": {"outputs": {"v": {"type": "float", "source": "i0.v"}}},)";
    std::string next = level == 0 ? "lib/fan_1.json" : "fan_" + std::to_string(level + 1) + ".json";
    tree.write(level == 0 ? "p.json" : "lib/fan_" + std::to_string(level) + ".json",
               head + R"( "imports": {"next": ")" + next + R"("}, "nodes": [)" + nodes + "]}");
  }
  Diagnostics diags;
  EXPECT_FALSE(loadGraphFile(tree.path("p.json"), diags));
  ASSERT_FALSE(diags.sorted().empty());
  EXPECT_EQ(diags.sorted()[0].code, DiagCode::LimitExceeded);
  EXPECT_NE(diags.sorted()[0].message.find("with every subgraph instance inlined"), std::string::npos);
}

// Files of 15 MiB each (a small graph padded with spaces): four pass, the fifth takes the
// imported bytes past 64 MiB.
TEST(Subgraph, AllImportedFilesTogetherAreLimited) {
  GraphTree tree;
  std::string padded = std::string(R"({"version": 1, "name": "pad", "interface": {"outputs": {"v": {"type": "float", "source": 1}}},
    "nodes": []})") + std::string(15u * 1024u * 1024u, ' ') + "\n";
  std::string imports, nodes;
  for (int i = 0; i < 5; ++i) {
    std::string n = std::to_string(i);
    tree.write("lib/pad" + n + ".json", padded);
    imports += std::string(i ? ", " : "") + "\"p" + n + "\": \"lib/pad" + n + ".json\"";
  }
  Diagnostics diags;
  EXPECT_FALSE(loadGraphFile(tree.write("p.json", R"({"version": 1, "name": "p", "imports": {)" + imports +
                                                      R"(}, "nodes": [], "outputs": {"fragment": {"alpha": 1}}})"),
                             diags));
  auto sorted = diags.sorted();
  ASSERT_EQ(sorted.size(), 1u) << diagnosticsText(diags);
  EXPECT_EQ(sorted[0].code, DiagCode::LimitExceeded);
  EXPECT_NE(sorted[0].message.find("import 'p4' would make the imported graph files"), std::string::npos)
      << sorted[0].message;
}

TEST(Subgraph, ATexturePathInASubgraphIsRelativeToItsFile) {
  GraphTree tree;
  fs::create_directories(tree.path("lib/textures"));
  fs::copy_file(test::sourcePath("graphs/lagoon_ripples.png"), tree.path("lib/textures/ripples.png"));
  tree.write("lib/tex.json", R"({"version": 1, "name": "tex",
    "interface": {"outputs": {"c": {"type": "vec3", "source": "t.rgb"}}},
    "nodes": [{"id": "t", "type": "texture_sample", "options": {"texture": "textures/ripples.png"}}]})");
  Built b = compileTree(tree.write("p.json", R"({"version": 1, "name": "p", "imports": {"tex": "lib/tex.json"},
    "nodes": [{"id": "x", "type": "tex"}], "outputs": {"fragment": {"color": "x.c"}}})"));
  ASSERT_TRUE(b.result) << diagnosticsText(b.diags);
  ASSERT_FALSE(b.result->manifest.textures.empty());
  EXPECT_EQ(b.result->manifest.textures[0].source, "lib/textures/ripples.png");
}

TEST(Subgraph, FunctionGraphsKeepTheirCanonicalForm) {
  for (const auto& name : test::listFiles(test::sourcePath("graphs/lib"), ".json")) {
    std::string path = test::sourcePath("graphs/lib/" + name);
    Diagnostics diags;
    std::string text = test::readFile(path);
    auto g = parseGraph(text, path, diags);
    ASSERT_TRUE(g) << diagnosticsText(diags);
    ASSERT_TRUE(g->interface) << name;
    EXPECT_EQ(saveGraph(*g), text) << name << " is not in the form `watergraph fmt` writes";
  }
}

TEST(Subgraph, EveryLibraryGraphCompilesOnItsOwnAndIsUsedByAnExample) {
  std::string users;
  for (const auto& g : test::exampleGraphs()) users += test::readFile(g);
  auto names = test::listFiles(test::sourcePath("graphs/lib"), ".json");
  EXPECT_GE(names.size(), 4u);
  for (const auto& name : names) {
    Built b = compileTree(test::sourcePath("graphs/lib/" + name));
    EXPECT_TRUE(b.result) << name << "\n" << diagnosticsText(b.diags);
    EXPECT_NE(users.find("\"lib/" + name + "\""), std::string::npos) << name << " is imported by no example graph";
  }
}

}  // namespace
}  // namespace wg
