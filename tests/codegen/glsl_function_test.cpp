// GLSL function nodes (docs/graph-format.md, "GLSL function nodes"): a node that calls a
// function of a .glsl file beside the graph. Its parameters and return value are its
// ports; the file is checked by glslang for every target before a byte of it reaches a
// shader, renamed into the node's namespace, and every bad file is one diagnostic at its
// place in the .glsl file (or at the node's option), naming the node.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <string>

#include "codegen/compile.h"
#include "codegen/cpu_backend.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg {
namespace {

namespace fs = std::filesystem;

// A folder of the test's files (test::FileTree), removed afterwards.
struct FunctionTree : test::FileTree {
  FunctionTree() : FileTree("wg_glsl_function") {}
};

// A small caustic: bright lines where two sine ridges cross, with a helper and a constant.
const char* kCaustic = R"(// A cheap caustic pattern.
const float K_TWO_PI = 6.28318530718;

float ridge(float x) {
  return 1.0 - abs(sin(x * K_TWO_PI));
}

float caustic(vec2 uv, float scale) {
  vec2 p = uv * scale;
  return ridge(p.x + 0.3 * sin(p.y)) * ridge(p.y + 0.3 * sin(p.x));
}

void split(vec3 c, out float luma, out vec3 tint) {
  luma = dot(c, vec3(0.2126, 0.7152, 0.0722));
  tint = c - vec3(luma);
}
)";

std::string graphCalling(const std::string& nodes, const std::string& color) {
  return test::graphJson(nodes, R"("fragment": {"color": )" + color + "}");
}

const char* kOneNode = R"({"id": "c", "type": "glsl_function",
  "options": {"file": "caustic.glsl", "function": "caustic"},
  "inputs": {"uv": [0.25, 0.5], "scale": 4}})";

struct Built {
  Diagnostics diags;
  std::optional<CompileResult> result;
};

Built compileIn(const FunctionTree& tree, const std::string& graph, CompileOptions options = {}) {
  Built b;
  auto g = loadGraphFile(tree.write("g.json", graph), b.diags);
  if (g) b.result = compileGraph(*g, defaultRegistry(), options, b.diags);
  return b;
}

std::string shaderText(const CompileResult& r, const std::string& suffix) {
  for (const auto& f : r.files)
    if (f.name.ends_with(suffix)) return f.contents;
  return "";
}

std::string firstMessage(const Diagnostics& d) {
  auto all = d.sorted();
  return all.empty() ? "" : all.front().where.file.str() + ":" + std::to_string(all.front().where.line) + ":" +
                                std::to_string(all.front().where.col) + ": " + all.front().message;
}

TEST(GlslFunctionNode, CompilesForEveryTargetWithItsFileRenamedIntoTheNodesNamespace) {
  FunctionTree tree;
  tree.write("caustic.glsl", kCaustic);
  Built b = compileIn(tree, graphCalling(kOneNode, "\"c.out\""));
  ASSERT_TRUE(b.result) << firstMessage(b.diags);
  std::string frag = shaderText(*b.result, ".glsl330.frag");
  EXPECT_NE(frag.find("float wgfn0_caustic(vec2 uv, float scale)"), std::string::npos) << frag;
  EXPECT_NE(frag.find("float wgfn0_ridge(float x)"), std::string::npos);
  EXPECT_NE(frag.find("const float wgfn0_K_TWO_PI"), std::string::npos);
  EXPECT_NE(frag.find("= wgfn0_caustic("), std::string::npos) << frag;
  // Members and swizzles are not names of the file: `p.x` stays as written.
  EXPECT_NE(frag.find("ridge(p.x + 0.3 * sin(p.y))"), std::string::npos);
  EXPECT_EQ(frag.find(" caustic("), std::string::npos) << "the file's own name must not reach the shader";
  EXPECT_FALSE(shaderText(*b.result, ".es300.frag").empty());
  EXPECT_EQ(b.result->program.functionFiles, std::vector<std::string>{"caustic.glsl"});
}

TEST(GlslFunctionNode, TwoNodesOfOneFileTakeTwoNamespaces) {
  FunctionTree tree;
  tree.write("caustic.glsl", kCaustic);
  std::string nodes = std::string(kOneNode) + R"(,
    {"id": "d", "type": "glsl_function", "options": {"file": "caustic.glsl", "function": "caustic"},
     "inputs": {"uv": "uv.out", "scale": 7}},
    {"id": "uv", "type": "uv"},
    {"id": "sum", "type": "add", "inputs": {"a": "c.out", "b": "d.out"}})";
  Built b = compileIn(tree, graphCalling(nodes, "\"sum.out\""));
  ASSERT_TRUE(b.result) << firstMessage(b.diags);
  std::string frag = shaderText(*b.result, ".glsl330.frag");
  EXPECT_NE(frag.find("wgfn0_caustic("), std::string::npos);
  EXPECT_NE(frag.find("wgfn1_caustic("), std::string::npos);
}

TEST(GlslFunctionNode, OutParametersAreOutputs) {
  FunctionTree tree;
  tree.write("caustic.glsl", kCaustic);
  std::string nodes = R"({"id": "s", "type": "glsl_function", "options": {"file": "caustic.glsl", "function": "split"},
     "inputs": {"c": [0.2, 0.5, 0.9]}},
    {"id": "mix", "type": "mul", "inputs": {"a": "s.tint", "b": "s.luma"}})";
  Built b = compileIn(tree, graphCalling(nodes, "\"mix.out\""));
  ASSERT_TRUE(b.result) << firstMessage(b.diags);
  std::string frag = shaderText(*b.result, ".glsl330.frag");
  EXPECT_NE(frag.find("wgfn0_split("), std::string::npos) << frag;
}

TEST(GlslFunctionNode, AReferenceFormulaIsTheNodesDoubleReference) {
  FunctionTree tree;
  tree.write("lin.glsl", "float lin(float a, float b) { return 2.0 * a + b; }\n");
  std::string nodes = R"({"id": "l", "type": "glsl_function",
     "options": {"file": "lin.glsl", "function": "lin", "reference": {"out": "2.0 * a + b"}},
     "inputs": {"a": "$a", "b": 0.5}})";
  std::string graph = test::graphJson(nodes, R"("fragment": {"color": "l.out"})",
                                      R"("a": {"type": "float", "default": 1.25})");
  Built b = compileIn(tree, graph);
  ASSERT_TRUE(b.result) << firstMessage(b.diags);
  CpuResult cpu = evaluateProgram(b.result->program, EvalEnvironment{});
  ASSERT_EQ(cpu.outputs.size(), 1u);
  EXPECT_DOUBLE_EQ(cpu.outputs[0][0], 3.0);
  // Constant inputs fold nothing: the GLSL is what runs, the reference only checks it.
  EXPECT_NE(shaderText(*b.result, ".glsl330.frag").find("wgfn0_lin("), std::string::npos);
}

TEST(GlslFunctionNode, WithoutAReferenceTheCpuSaysSoPlainly) {
  FunctionTree tree;
  tree.write("caustic.glsl", kCaustic);
  Built b = compileIn(tree, graphCalling(kOneNode, "\"c.out\""));
  ASSERT_TRUE(b.result) << firstMessage(b.diags);
  try {
    evaluateProgram(b.result->program, EvalEnvironment{});
    FAIL() << "evaluated a node that has no reference";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("has no double reference"), std::string::npos) << e.what();
  }
}

// ---- bad input: one diagnostic at its place, naming the node, and no program ---------------

struct FunctionFault {
  DiagCode code;
  std::string file;  // the diagnostic's file name ends with this
  int line, col;
};

void expectFault(const std::string& glsl, const std::string& function, const FunctionFault& want,
                 const std::string& messagePart) {
  FunctionTree tree;
  tree.write("f.glsl", glsl);
  std::string node = R"({"id": "fn", "type": "glsl_function", "options": {"file": "f.glsl", "function": ")" + function +
                     R"("}, "inputs": {}})";
  Built b = compileIn(tree, graphCalling(node, "0.5"));
  EXPECT_FALSE(b.result);
  auto all = b.diags.sorted();
  ASSERT_FALSE(all.empty());
  const Diagnostic& d = all.front();
  EXPECT_EQ(d.code, want.code) << firstMessage(b.diags);
  EXPECT_TRUE(d.where.file.str().ends_with(want.file)) << firstMessage(b.diags);
  if (want.line > 0) {  // 0: a place in the graph file, which graphJson lays out
    EXPECT_EQ(d.where.line, want.line) << firstMessage(b.diags);
    EXPECT_EQ(d.where.col, want.col) << firstMessage(b.diags);
  }
  EXPECT_EQ(d.node, "fn");
  EXPECT_NE(d.message.find(messagePart), std::string::npos) << d.message;
}

TEST(GlslFunctionNodeBadInput, AFileThatDoesNotParse) {
  expectFault("float f(float a) {\n  return a +* 2.0;\n}\n", "f", {DiagCode::FunctionFileSyntax, "f.glsl", 2, 3},
              "syntax error");
}

TEST(GlslFunctionNodeBadInput, AnUndeclaredNameIsFoundAtItsColumn) {
  expectFault("float f(float a) {\n  return a * u_time;\n}\n", "f", {DiagCode::FunctionFileSyntax, "f.glsl", 2, 14},
              "undeclared identifier");
}

// glslang counts lines at LF alone (a CRLF's LF; a lone CR ends none), and so does the column
// finder: the error is on the line glslang names, whichever end the file's lines have.
TEST(GlslFunctionNodeBadInput, AnUndeclaredNameIsFoundAtItsColumnWhateverTheLineEnds) {
  expectFault("float f(float a) {\r\n  return a * u_time;\r\n}\r\n", "f", {DiagCode::FunctionFileSyntax, "f.glsl", 2, 14},
              "undeclared identifier");
  expectFault("float f(float a) {\r  return a * u_time;\r}\r\nconst float g = 1.0;\n", "f", {DiagCode::FunctionFileSyntax, "f.glsl", 1, 33},
              "undeclared identifier");
}

// A file that ends inside a declaration glslang alone sees unfinished (a lone CR ends the
// comment, not the line): glslang finds the error in the empty main() the check reads after
// the file, on a line the file does not have; it is placed where the file ends, and says so.
TEST(GlslFunctionNodeBadInput, AFileEndingInsideADeclarationIsPlacedAtItsEnd) {
  expectFault("// a comment\rfloat f(out\rvec3", "f", {DiagCode::FunctionFileSyntax, "f.glsl", 1, 30},
              "the file ends inside a declaration");
}

TEST(GlslFunctionNodeBadInput, OneTargetRefusingIsEnough) {
  // GLSL 3.30 converts the int; GLSL ES 3.00 converts nothing implicitly.
  expectFault("float f(float a) {\n  return a + 1;\n}\n", "f", {DiagCode::FunctionFileSyntax, "f.glsl", 2, 12}, "es300");
}

TEST(GlslFunctionNodeBadInput, AFunctionThatDoesNotExist) {
  expectFault("float g(float a) { return a; }\n", "f", {DiagCode::FunctionNotFound, "g.json", 0, 0}, "defines: g");
}

TEST(GlslFunctionNodeBadInput, AnOverloadedFunction) {
  expectFault("float f(float a) { return a; }\nvec2 f(vec2 a) { return a; }\n", "f",
              {DiagCode::FunctionNotFound, "f.glsl", 2, 6}, "overloaded");
}

TEST(GlslFunctionNodeBadInput, Recursion) {
  expectFault("float g(float a);\nfloat f(float a) { return a < 1.0 ? a : g(a * 0.5); }\n"
              "float g(float a) { return f(a); }\n",
              "f", {DiagCode::FunctionRecursion, "f.glsl", 2, 7}, "f -> g -> f");
}

TEST(GlslFunctionNodeBadInput, AParameterTypeNoPortCarries) {
  expectFault("float f(mat2 m) { return m[0][0]; }\n", "f", {DiagCode::FunctionPortType, "f.glsl", 1, 14}, "mat2");
  expectFault("float f(int n) { return float(n); }\n", "f", {DiagCode::FunctionPortType, "f.glsl", 1, 13}, "int");
  expectFault("void f(inout vec3 c) { c *= 2.0; }\n", "f", {DiagCode::FunctionPortType, "f.glsl", 1, 19}, "inout");
}

TEST(GlslFunctionNodeBadInput, ForbiddenDeclarations) {
  expectFault("uniform float u_time;\nfloat f(float a) { return a; }\n", "f",
              {DiagCode::FunctionForbidden, "f.glsl", 1, 1}, "'uniform'");
  expectFault("float f(float a) { return a; }\nout vec4 color;\n", "f", {DiagCode::FunctionForbidden, "f.glsl", 2, 1},
              "'out'");
  expectFault("#version 450\nfloat f(float a) { return a; }\n", "f", {DiagCode::FunctionForbidden, "f.glsl", 1, 1},
              "#version");
  expectFault("#extension GL_OES_standard_derivatives : enable\nfloat f(float a) { return a; }\n", "f",
              {DiagCode::FunctionForbidden, "f.glsl", 1, 1}, "#extension");
  expectFault("float f(float a) { return a; }\nvoid main() {}\n", "f", {DiagCode::FunctionForbidden, "f.glsl", 2, 6},
              "'main'");
  expectFault("float g = 1.0;\nfloat f(float a) { return a * g; }\n", "f", {DiagCode::FunctionForbidden, "f.glsl", 1, 1},
              "constant");
}

TEST(GlslFunctionNodeBadInput, ANameThatWouldClashAfterRenaming) {
  expectFault("float h(float a) { return a; }\nfloat f(float a) { float wgfn0_h = 1.0; return h(a) + wgfn0_h; }\n", "f",
              {DiagCode::FunctionNameClash, "f.glsl", 2, 26}, "clash after renaming");
  expectFault("float wg_fresnel(float a) { return a; }\n", "wg_fresnel", {DiagCode::FunctionNameClash, "f.glsl", 1, 7},
              "reserved");
}

void expectUnusable(const FunctionTree& tree, const std::string& file, const std::string& messagePart) {
  std::string node = R"({"id": "fn", "type": "glsl_function", "options": {"file": ")" + file +
                     R"(", "function": "f"}, "inputs": {}})";
  Built b = compileIn(tree, graphCalling(node, "0.5"));
  EXPECT_FALSE(b.result);
  auto all = b.diags.sorted();
  ASSERT_FALSE(all.empty());
  EXPECT_EQ(all.front().code, DiagCode::FunctionFileUnusable) << firstMessage(b.diags);
  EXPECT_TRUE(all.front().where.file.str().ends_with("g.json"));
  EXPECT_EQ(all.front().node, "fn");
  EXPECT_NE(all.front().message.find(messagePart), std::string::npos) << all.front().message;
}

TEST(GlslFunctionNodeBadInput, A16MiBFile) {
  FunctionTree tree;
  tree.write("big.glsl", "float f(float a) { return a; }\n" + std::string(16u << 20, ' '));
  expectUnusable(tree, "big.glsl", "larger than");
}

TEST(GlslFunctionNodeBadInput, AFifo) {
  FunctionTree tree;
  ASSERT_EQ(mkfifo((tree.dir() + "/pipe.glsl").c_str(), 0600), 0);
  expectUnusable(tree, "pipe.glsl", "not a regular file");
}

TEST(GlslFunctionNodeBadInput, ASymlinkOutOfTheFolder) {
  FunctionTree outside;
  std::string target = outside.write("f.glsl", "float f(float a) { return a; }\n");
  FunctionTree tree;
  fs::create_symlink(target, tree.dir() + "/f.glsl");
  expectUnusable(tree, "f.glsl", "outside the graph's folder");
  expectUnusable(tree, "../f.glsl", "leaves the graph's folder");
  expectUnusable(tree, "missing.glsl", "cannot be read");
}

TEST(GlslFunctionNodeCli, TheDepfileListsTheFunctionFile) {
  FunctionTree tree;
  tree.write("caustic.glsl", kCaustic);
  std::string graph = tree.write("g.json", graphCalling(kOneNode, "\"c.out\""));
  auto r = test::runWatergraph("compile " + test::shellQuote(graph) + " -o " + test::shellQuote(tree.dir() + "/out") +
                               " --depfile " + test::shellQuote(tree.dir() + "/g.d"));
  ASSERT_EQ(r.exit, 0) << r.out << r.err;
  EXPECT_NE(test::readFile(tree.dir() + "/g.d").find("caustic.glsl"), std::string::npos);
}

TEST(GlslFunctionNodeCli, ABadFileIsExitOneAtItsLineAndNothingIsWritten) {
  FunctionTree tree;
  tree.write("f.glsl", "float f(float a) {\n  return a * u_time;\n}\n");
  std::string graph = tree.write(
      "g.json", graphCalling(R"({"id": "fn", "type": "glsl_function", "options": {"file": "f.glsl", "function": "f"},
                                "inputs": {"a": 1}})",
                             "\"fn.out\""));
  auto r = test::runWatergraph("compile " + test::shellQuote(graph) + " -o " + test::shellQuote(tree.dir() + "/out"));
  EXPECT_EQ(r.exit, 1) << r.out << r.err;
  EXPECT_NE(r.err.find("f.glsl:2:14: error: [WG081]"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("node 'fn'"), std::string::npos) << r.err;
  EXPECT_TRUE(test::listFilesRecursive(tree.dir() + "/out").empty());
}

}  // namespace
}  // namespace wg
