// The `expression` node in graphs: resolve expands its formula into math-node ops that go
// through the passes like hand-wired nodes (folding, CSE across formulas, pruning), its
// output feeds other nodes and output slots, and every fault in a formula or in the
// declared inputs is one diagnostic at the character of the file it is about (escapes in
// the JSON string counted), naming the node and the option or input.
#include <gtest/gtest.h>

#include <string>

#include "codegen/compile.h"
#include "codegen/probe_program.h"
#include "core/expand.h"
#include "core/graph_io.h"
#include "core/resolve.h"
#include "nodes/registry.h"

namespace wg {
namespace {

// A graph whose colour is `formula` over inputs a (float, from a parameter) and c (vec3,
// from a parameter); `extraNodes` go into the node list. The formula is the only thing on
// line 8, after `    "formula": "` (so its first character is at column 17).
std::string graphWith(const std::string& formulaAsWritten, const std::string& inputs = R"({"a": "float", "c": "vec3"})",
                      const std::string& wiring = R"({"a": "$a", "c": "$c"})", const std::string& extraNodes = "",
                      const std::string& color = "e.out") {
  return "{\n"
         "  \"version\": 1, \"name\": \"g\",\n"
         "  \"parameters\": {\"a\": {\"type\": \"float\", \"default\": 0.5},\n"
         "                 \"c\": {\"type\": \"vec3\", \"default\": [0.1, 0.2, 0.3]}},\n"
         "  \"nodes\": [" + extraNodes + "\n"
         "   {\"id\": \"e\", \"type\": \"expression\",\n"
         "    \"inputs\": " + wiring + ", \"options\": {\"inputs\": " + inputs + ",\n"
         "    \"formula\": \"" + formulaAsWritten + "\"}}],\n"
         "  \"outputs\": {\"fragment\": {\"color\": \"" + color + "\"}}\n"
         "}\n";
}
constexpr int kFormulaLine = 8;
constexpr int kFormulaColumn = 17;

struct Compiled {
  std::optional<CompileResult> result;
  Diagnostics diags;
};

// The glsl330 fragment shader of a compiled graph.
std::string fragment(const CompileResult& r) {
  for (const auto& f : r.files)
    if (f.name.ends_with(".glsl330.frag")) return f.contents;
  return "";
}

Compiled compile(const std::string& text) {
  Compiled c;
  auto graph = parseGraph(text, "g.json", c.diags);
  if (graph) c.result = compileGraph(*graph, defaultRegistry(), CompileOptions{}, c.diags);
  return c;
}

std::string allText(const Diagnostics& d) {
  std::string s;
  for (const auto& x : d.sorted()) s += formatText(x) + "\n";
  return s;
}

// The one error a faulty graph gives: code, line:col and message.
struct Fault {
  std::string code;
  int line = 0, col = 0;
  std::string message;
  std::string port;
};

Fault fault(const std::string& text) {
  Compiled c = compile(text);
  EXPECT_FALSE(c.result) << text;
  EXPECT_EQ(c.diags.errorCount(), 1u) << allText(c.diags);
  if (c.diags.all().empty()) return {};
  std::vector<Diagnostic> sorted = c.diags.sorted();
  const Diagnostic& d = sorted.front();
  if (d.code != DiagCode::LimitExceeded) {  // the loader's limit names no node
    EXPECT_EQ(d.node, "e");
  }
  return {codeString(d.code), d.where.line, d.where.col, d.message, d.port};
}

TEST(ExpressionNode, CompilesForEveryTargetAndFeedsTheOutput) {
  Compiled c = compile(graphWith("mix(c, vec3(1.0), clamp(a, 0.0, 1.0)) * 0.5"));
  ASSERT_TRUE(c.result) << allText(c.diags);
  const std::string frag = fragment(*c.result);
  EXPECT_NE(frag.find("mix("), std::string::npos) << frag;
  EXPECT_NE(frag.find("clamp("), std::string::npos) << frag;
}

TEST(ExpressionNode, ItsOutputFeedsAnotherNode) {
  // The expression's value into a built-in node, the node's output into a second formula.
  std::string extra = R"(
   {"id": "t", "type": "depth_tint", "inputs": {"depth": "e.out"}},
   {"id": "f", "type": "expression", "inputs": {"col": "t.color"},
    "options": {"inputs": {"col": "vec3"}, "formula": "col.bgr"}},)";
  Compiled c = compile(graphWith("a * 4.0", R"({"a": "float"})", R"({"a": "$a"})", extra, "f.out"));
  ASSERT_TRUE(c.result) << allText(c.diags);
}

TEST(ExpressionNode, ConstantFormulasFoldAway) {
  Compiled c = compile(graphWith("vec3(exp(0.0), 2.0 * 0.25, sqrt(16.0))", R"({})", R"({})"));
  ASSERT_TRUE(c.result) << allText(c.diags);
  const std::string frag = fragment(*c.result);
  EXPECT_NE(frag.find("vec3(1.0, 0.5, 4.0)"), std::string::npos) << frag;
  EXPECT_EQ(frag.find("wg_safe_sqrt"), std::string::npos) << frag;
}

TEST(ExpressionNode, TwoFormulasComputingTheSameShareOneOp) {
  // e and e2 both compute exp(-a) * c: CSE leaves one exp in the shader.
  std::string extra = R"(
   {"id": "e2", "type": "expression", "inputs": {"x": "$a", "y": "$c"},
    "options": {"inputs": {"x": "float", "y": "vec3"}, "formula": "exp(-x) * y"}},
   {"id": "sum", "type": "add", "inputs": {"a": "e.out", "b": "e2.out"}},)";
  Compiled c = compile(graphWith("exp(-a) * c", R"({"a": "float", "c": "vec3"})", R"({"a": "$a", "c": "$c"})", extra, "sum.out"));
  ASSERT_TRUE(c.result) << allText(c.diags);
  const std::string frag = fragment(*c.result);
  size_t first = frag.find("wg_safe_exp_float(");
  ASSERT_NE(first, std::string::npos) << frag;
  // The library defines it once and the body calls it once.
  size_t calls = 0;
  for (size_t at = frag.find("= wg_safe_exp_float("); at != std::string::npos; at = frag.find("= wg_safe_exp_float(", at + 1)) ++calls;
  EXPECT_EQ(calls, 1u) << frag;
}

TEST(ExpressionNode, AFloatSplatsIntoADeclaredVector) {
  Compiled c = compile(graphWith("c * 2.0", R"({"c": "vec3"})", R"({"c": "$a"})"));
  ASSERT_TRUE(c.result) << allText(c.diags);
  Compiled literal = compile(graphWith("c * 2.0", R"({"c": "vec3"})", R"({"c": 0.25})"));
  ASSERT_TRUE(literal.result) << allText(literal.diags);
}

TEST(ExpressionNode, ProbeReadsItsOutput) {
  Diagnostics diags;
  auto graph = parseGraph(graphWith("c * a"), "g.json", diags);
  ASSERT_TRUE(graph);
  auto program = buildProbeProgram(*graph, defaultRegistry(), ProbeOutput{"e", "out"}, diags);
  ASSERT_TRUE(program) << allText(diags);
  ASSERT_EQ(program->outputs.size(), 1u);
  EXPECT_EQ(program->outputs[0].type, Type::Vec3);
  auto missing = buildProbeProgram(*graph, defaultRegistry(), ProbeOutput{"e", "outt"}, diags);
  EXPECT_FALSE(missing);
  EXPECT_NE(allText(diags).find("has no output 'outt' (did you mean 'out'?)"), std::string::npos) << allText(diags);
}

TEST(ExpressionNode, UnknownFunctionIsPlacedAtItsNameWithASuggestion) {
  Fault f = fault(graphWith("c * mixx(a, 1.0, 0.5)"));
  EXPECT_EQ(f.code, "WG038");
  EXPECT_EQ(f.line, kFormulaLine);
  EXPECT_EQ(f.col, kFormulaColumn + 4);
  EXPECT_EQ(f.message, "unknown function 'mixx' (did you mean 'mix'?)");
  EXPECT_EQ(f.port, "option 'formula'");
}

TEST(ExpressionNode, ColumnsCountTheEscapesBeforeTheFault) {
  // \t (2 bytes for 1), \u0020 (6 bytes for 1) and \\u00e9 written as \u00e9 (6 bytes for
  // the 2 bytes of é) before the unknown name `zz`: decoded offset 1 + 1 + 1 + 1 = 4 ...
  // the file column counts what is written.
  std::string written = R"(a\t+\u0020zz)";
  Fault f = fault(graphWith(written));
  EXPECT_EQ(f.code, "WG038");
  EXPECT_EQ(f.line, kFormulaLine);
  EXPECT_EQ(f.col, kFormulaColumn + static_cast<int>(written.find("zz")));
  EXPECT_NE(f.message.find("unknown input 'zz'"), std::string::npos) << f.message;
  // A multi-byte character written raw counts its bytes; escaped, its escape.
  std::string raw = "a + \xC3\xA9";  // é: the lexer stops at its first byte
  Fault r = fault(graphWith(raw));
  EXPECT_EQ(r.code, "WG037");
  EXPECT_EQ(r.col, kFormulaColumn + 4);
  std::string escaped = R"(a \u002b \u00e9)";
  Fault e = fault(graphWith(escaped));
  EXPECT_EQ(e.code, "WG037");
  EXPECT_EQ(e.col, kFormulaColumn + static_cast<int>(escaped.find("\\u00e9")));
}

TEST(ExpressionNode, SyntaxErrorsAreWG037AtTheToken) {
  Fault f = fault(graphWith("(a + c"));
  EXPECT_EQ(f.code, "WG037");
  EXPECT_EQ(f.line, kFormulaLine);
  EXPECT_EQ(f.col, kFormulaColumn + 6);  // the end of the formula, where ')' is missing
  Fault g = fault(graphWith("a + * c"));
  EXPECT_EQ(g.code, "WG037");
  EXPECT_EQ(g.col, kFormulaColumn + 4);
}

TEST(ExpressionNode, NestingBeyondTheLimitIsOneClearError) {
  std::string deep(100, '(');
  deep += "a" + std::string(100, ')');
  Fault f = fault(graphWith(deep));
  EXPECT_EQ(f.code, "WG037");
  EXPECT_NE(f.message.find("64"), std::string::npos) << f.message;
}

TEST(ExpressionNode, TypeErrorsAreWG038) {
  Fault f = fault(graphWith("c + c.xy"));
  EXPECT_EQ(f.code, "WG038");
  EXPECT_EQ(f.line, kFormulaLine);
  Fault cmp = fault(graphWith("a < 1.0"));
  EXPECT_EQ(cmp.code, "WG038");
}

TEST(ExpressionNode, DeclaredInputsAreCheckedLikePorts) {
  // A declared input left unconnected.
  Fault missing = fault(graphWith("a + 1.0", R"({"a": "float", "b": "float"})", R"({"a": "$a"})"));
  EXPECT_EQ(missing.code, "WG023");
  EXPECT_EQ(missing.port, "input 'b'");
  // A wire to an input the node does not declare.
  Fault unknown = fault(graphWith("a", R"({"a": "float"})", R"({"a": "$a", "b": "$a"})"));
  EXPECT_EQ(unknown.code, "WG021");
  // A vec3 into a declared float.
  Fault type = fault(graphWith("a", R"({"a": "float"})", R"({"a": "$c"})"));
  EXPECT_EQ(type.code, "WG029");
  EXPECT_EQ(type.port, "input 'a'");
  EXPECT_NE(type.message.find("expects float"), std::string::npos) << type.message;
}

TEST(ExpressionNode, DeclarationsThatAreNotInputsAreRefused) {
  for (const char* inputs : {R"({"a": "mat4"})", R"({"a b": "float"})", R"({"": "float"})", R"(["a"])", R"({"a": 3})"}) {
    Fault f = fault(graphWith("1.0", inputs, "{}"));
    EXPECT_EQ(f.code, "WG030") << inputs;
    EXPECT_EQ(f.port, "option 'inputs'") << inputs;
  }
}

TEST(ExpressionNode, AFormulaLongerThanAStringOfTheFormatIsRefusedWhenSet) {
  // The loader refuses any string over 4096 bytes (WG035); a formula set in memory (the
  // editor) is held to the same limit, so what is set can be saved and loaded again.
  Fault loaded = fault(graphWith(std::string(5000, '1'), R"({})", "{}"));
  EXPECT_EQ(loaded.code, "WG035");
  Diagnostics diags;
  auto graph = parseGraph(graphWith("1.0", R"({})", "{}"), "g.json", diags);
  ASSERT_TRUE(graph);
  for (auto& o : graph->nodes.back().options)
    if (o.name == "formula") o.value = std::string(5000, '1');
  EXPECT_FALSE(resolveGraph(*graph, defaultRegistry(), diags));
  ASSERT_EQ(diags.errorCount(), 1u);
  EXPECT_EQ(codeString(diags.all()[0].code), "WG030");
  EXPECT_NE(diags.all()[0].message.find("at most 4096"), std::string::npos) << diags.all()[0].message;
}

// What the editor shows as a formula is typed: the fault with its byte in the formula,
// from the same expansion resolve runs, without a graph around the node.
TEST(ExpressionNode, TheExpansionsFaultIsFoundWithoutAGraph) {
  const NodeSpec& spec = *defaultRegistry().find("expression");
  nlohmann::json declared = {{"c", "vec3"}, {"k", "float"}};
  auto fault = expansionFault(defaultRegistry(), spec, {{"inputs", declared}, {"formula", "c * mixx(k)"}});
  ASSERT_TRUE(fault);
  EXPECT_EQ(fault->option, "formula");
  EXPECT_EQ(fault->offset, 4u);
  EXPECT_EQ(fault->message, "unknown function 'mixx' (did you mean 'mix'?)");
  auto typeFault = expansionFault(defaultRegistry(), spec, {{"inputs", declared}, {"formula", "c + vec2(k)"}});
  ASSERT_TRUE(typeFault);
  EXPECT_EQ(typeFault->offset, 0u);
  EXPECT_FALSE(expansionFault(defaultRegistry(), spec, {{"inputs", declared}, {"formula", "c * k"}}));
  // Options that are not valid are checkOption's to report, not the expansion's.
  EXPECT_FALSE(expansionFault(defaultRegistry(), spec, {{"inputs", {{"c", "colour"}}}, {"formula", "c"}}));
}

TEST(ExpressionNode, DiagnosticsOfAGraphBuiltInMemoryStillNameTheOption) {
  // No file text to count escapes in: the position falls back to the option's own.
  Graph g;
  g.file = "mem.json";
  g.name = "mem";
  Node n;
  n.id = "e";
  n.type = "expression";
  NodeOption formula{"formula", "nosuch", {}, {}};
  formula.where = SourceRef{"mem.json", 3, 10};
  n.options.push_back(formula);
  n.options.push_back({"inputs", nlohmann::json::object(), {}, {}});
  g.nodes.push_back(n);
  GraphOutput out;
  out.slot = OutputSlot::FragmentAlpha;
  out.source.kind = InputSource::Kind::NodeOutput;
  out.source.name = "e";
  out.source.port = "out";
  g.outputs.push_back(out);
  Diagnostics diags;
  EXPECT_FALSE(resolveGraph(g, defaultRegistry(), diags));
  ASSERT_EQ(diags.errorCount(), 1u) << allText(diags);
  EXPECT_EQ(diags.all()[0].where.line, 3);
  EXPECT_EQ(diags.all()[0].where.col, 11);
}

}  // namespace
}  // namespace wg
