// The `expression` node: a formula in a GLSL-like language over inputs the node declares,
// e.g. "mix(shallow, deep, 1.0 - exp(-k * d))". It has no GLSL or double reference of its
// own: resolve expands it into ops of the math nodes (core/expression_lowering.h), so the
// guards, value facts, passes, probe and hard cases of those nodes apply to the formula
// exactly as if the nodes had been wired by hand.
#include <map>
#include <set>
#include <string>

#include "core/expand.h"
#include "core/expression_lowering.h"
#include "core/expression_parser.h"
#include "core/expression_types.h"
#include "core/graph.h"
#include "core/load_limits.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"

namespace wg::nodes {
namespace {

constexpr std::size_t kMaxFormulaInputs = 32;

struct ExpressionOptions {
  std::string formula;
  expr::FormulaInputs inputs;  // in the order of the ports: by name, as JSON objects keep them
};

ExpressionOptions parseExpressionOptions(const OptionReader& o) {
  ExpressionOptions r{o.text("formula"), {}};
  const nlohmann::json& declared = o.json("inputs");
  for (auto it = declared.begin(); it != declared.end(); ++it)
    r.inputs.emplace_back(it.key(), *parseType(it.value().get<std::string>()));
  return r;
}

std::string checkDeclaredInputs(const nlohmann::json& v) {
  if (!v.is_object()) return "must be an object: {\"name\": \"float\" | \"vec2\" | \"vec3\" | \"vec4\", ...}";
  if (v.size() > kMaxFormulaInputs) return "declares " + std::to_string(v.size()) + " inputs; at most " + std::to_string(kMaxFormulaInputs);
  for (auto it = v.begin(); it != v.end(); ++it) {
    const std::string& name = it.key();
    if (!isIdentifier(name)) return "declares '" + name + "', which is not an identifier";
    auto type = it.value().is_string() ? parseType(it.value().get<std::string>()) : std::nullopt;
    if (!type || !isFloatScalarOrVector(*type))
      return "gives input '" + name + "' the type " + it.value().dump() + "; it must be \"float\", \"vec2\", \"vec3\" or \"vec4\"";
  }
  return "";
}

// A formula is a string of the graph file, so it is held to the loader's limit on every
// string (which is below the parser's own kMaxFormulaLength): what an editor sets can be
// saved and loaded again.
std::string checkFormulaText(const nlohmann::json& v) {
  std::size_t n = v.get_ref<const std::string&>().size();
  if (n > kMaxStringBytes)
    return "is " + std::to_string(n) + " bytes long; a formula is at most " + std::to_string(kMaxStringBytes);
  return "";
}

// "abs, acos, ..., atan (1 or 2 arguments), ...": the functions a formula may call, by name.
std::string functionList() {
  std::map<std::string_view, std::set<int>> arities;
  for (const auto& f : expr::formulaFunctions()) arities[f.name].insert(f.arity);
  std::string list;
  for (const auto& [name, counts] : arities)
    list += (list.empty() ? "" : ", ") + std::string(name) + (counts.size() > 1 ? " (1 or 2 arguments)" : "");
  return list;
}

NodePorts expressionPorts(const ParsedOptions& options) {
  NodePorts ports;
  for (const auto& [name, type] : options.as<ExpressionOptions>().inputs)
    ports.inputs.push_back(ports::fixed(name, type, "declared by option 'inputs'"));
  ports.outputs = {ports::custom("out", "the formula's value: float or vecN, by GLSL's rules")};
  return ports;
}

void expandExpression(ExpandContext& ctx) {
  const auto& o = ctx.options.as<ExpressionOptions>();
  auto refuse = [&](DiagCode code, const expr::FormulaError& e) {
    ctx.errorCode = code;
    ctx.error = e.message;
    ctx.errorOption = "formula";
    ctx.errorOffset = e.span.offset;
  };
  auto parsed = expr::parseFormula(o.formula);
  if (const auto* e = std::get_if<expr::FormulaError>(&parsed)) return refuse(DiagCode::FormulaSyntax, *e);
  const expr::Ast& ast = std::get<expr::Ast>(parsed);
  auto typed = expr::typeFormula(ast, o.inputs);
  if (const auto* e = std::get_if<expr::FormulaError>(&typed)) return refuse(DiagCode::FormulaType, *e);
  expr::LoweringContext lowering;
  lowering.registry = &ctx.registry;
  lowering.nodeId = ctx.nodeId;
  for (std::size_t i = 0; i < o.inputs.size(); ++i) lowering.inputs[o.inputs[i].first] = ctx.inputs[i];
  lowering.where = [&](expr::Span s) { return ctx.optionWhere("formula", s.offset); };
  auto lowered = expr::lowerFormula(ast, std::get<std::vector<Type>>(typed), lowering, ctx.program);
  if (const auto* e = std::get_if<expr::FormulaError>(&lowered)) return refuse(DiagCode::FormulaType, *e);
  ctx.outputs = {std::get<expr::LoweredFormula>(lowered).value};
}

// The finite-output promise through formulas: each operator and call is the guarded node
// of its name, so a formula meets log(0), sqrt(-1), acos(1 + 1e-7), mod(x, 0), atan(0, 0),
// exp(100), inversesqrt(0), tan(pi/2) and the sky depth as those nodes do. ('/' is the div
// node: IEEE division, x / 0 an infinity as on the GPU, as docs/nodes.md says.)
std::vector<HardCase> formulaHardCases() {
  auto one = [](std::string name, std::string formula, std::vector<std::pair<std::string, double>> inputs,
                std::string expectation, double lo = -1e30, double hi = 1e30) {
    HardCase c;
    c.name = std::move(name);
    nlohmann::json declared = nlohmann::json::object();
    for (const auto& [input, value] : inputs) {
      declared[input] = "float";
      c.inputs.emplace_back(input, Value::scalar(value));
    }
    c.options = {{"formula", std::move(formula)}, {"inputs", declared}};
    c.expectation = std::move(expectation);
    c.lo = lo;
    c.hi = hi;
    return c;
  };
  const double pi = 3.14159265358979323846;
  return {
      one("log(0)", "log(x)", {{"x", 0}}, "the log node's guard: finite, not -inf"),
      one("sqrt(-1)", "sqrt(x)", {{"x", -1}}, "the sqrt node's guard: 0, not NaN", 0, 0),
      one("acos just past 1", "acos(x)", {{"x", 1.0000001}}, "argument clamped to [-1, 1]: 0, not NaN", 0, pi),
      one("mod(x, 0)", "mod(x, y)", {{"x", 3}, {"y", 0}}, "the mod node's guard: finite"),
      one("atan(0, 0)", "atan(y, x)", {{"y", 0}, {"x", 0}}, "the atan2 node's guard: finite, in [-pi, pi]", -pi, pi),
      one("exp(100)", "exp(x)", {{"x", 100}}, "capped below float overflow: finite", 0, 3.5e38),
      one("inversesqrt(0)", "inversesqrt(x)", {{"x", 0}}, "the inversesqrt node's guard: finite, not +inf"),
      one("tan(pi/2)", "tan(x)", {{"x", pi / 2}}, "finite near the pole"),
      one("Beer-Lambert at the sky", "mix(a, b, 1.0 - exp(-k * d))", {{"a", 0.2}, {"b", 0.9}, {"k", 0.4}, {"d", 1e30}},
          "exp underflows to 0: the deep value b, finite", 0.2, 0.9),
  };
}

}  // namespace

NodeSpec expressionNode() {
  NodeSpec s;
  s.type = "expression";
  s.family = "math";
  s.summary = "A formula over declared inputs, in GLSL's expression syntax, built from the math nodes.";
  s.formula =
      "out = the formula. Literals, the declared inputs, + - * /, unary minus, comparisons (< <= > >= == !=) "
      "only as the condition of ?:, swizzles (.xyz, .rgb, .stp), vec2/vec3/vec4 constructors and calls to the "
      "math vocabulary (" + functionList() + "). Types follow GLSL: a float meets a vector component-wise, the "
      "result type is inferred. Each operator and call becomes the op of the node of that name, with its guards "
      "(log(0), sqrt(-1), acos(1.0000001) stay finite as those nodes document; '/' is the div node, IEEE "
      "division as on the GPU).";
  s.cost = "the sum of the nodes it expands into; the passes fold constants and merge repeats across formulas";
  s.outputs = {ports::custom("out", "the formula's value: float or vecN, by GLSL's rules")};
  s.options = {
      ports::checked(OptionSpec::Kind::Text, "formula", "x", checkFormulaText,
                     "the formula, e.g. \"mix(shallow, deep, 1.0 - exp(-k * d))\" (at most 4096 bytes, 64 levels of "
                     "brackets, calls and ?: inside each other)"),
      ports::checked(OptionSpec::Kind::Json, "inputs", {{"x", "float"}}, checkDeclaredInputs,
                     "the inputs the formula reads and their types: {\"name\": \"float\" | \"vec2\" | \"vec3\" | "
                     "\"vec4\"} (at most 32); each is an input port of the node, required")};
  s.parseOptions = optionParser(parseExpressionOptions);
  s.hardCases = formulaHardCases();
  s.portsFor = expressionPorts;
  s.expand = expandExpression;
  // The probe holds an expression to the bound of the ops it expands into; this is the
  // math nodes' own bound, for the docs.
  s.tolerance = 1e-6;
  return s;
}

}  // namespace wg::nodes
