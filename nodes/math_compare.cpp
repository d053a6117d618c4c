// The comparison vocabulary: compare (a comparison as 0 or 1), select (a comparison
// choosing one of two values) and inverse_mix (where x lies between a and b), component-
// wise on float/vec2/vec3/vec4. Comparisons of floats are exact, so compare and select
// carry no input roundings of their own; inverse_mix guards the empty range a == b.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/math_builders.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"

namespace wg::nodes {
namespace {

enum class Comparison { Less, LessEqual, Greater, GreaterEqual, Equal, NotEqual };

struct ComparisonOptions {
  Comparison op;
};
ComparisonOptions parseComparisonOptions(const OptionReader& o) {
  return {o.choice<Comparison>("op", {{"less", Comparison::Less},
                                      {"less_equal", Comparison::LessEqual},
                                      {"greater", Comparison::Greater},
                                      {"greater_equal", Comparison::GreaterEqual},
                                      {"equal", Comparison::Equal},
                                      {"not_equal", Comparison::NotEqual}})};
}

OptionSpec comparisonOption() {
  return ports::choice("op", {"less", "less_equal", "greater", "greater_equal", "equal", "not_equal"}, "less",
                       "the comparison a OP b: <, <=, >, >=, ==, != (exact on floats)");
}

bool holds(Comparison op, double a, double b) {
  switch (op) {
    case Comparison::Less: return a < b;
    case Comparison::LessEqual: return a <= b;
    case Comparison::Greater: return a > b;
    case Comparison::GreaterEqual: return a >= b;
    case Comparison::Equal: return a == b;
    case Comparison::NotEqual: return a != b;
  }
  return false;
}

// The comparison as a GLSL bool (float) or bvecN (vectors: GLSL's operators compare
// scalars only, so vectors use lessThan and its kin).
GlslExpr condition(Comparison op, Type t, const GlslExpr& a, const GlslExpr& b) {
  static const char* const scalar[] = {"<", "<=", ">", ">=", "==", "!="};
  static const char* const vector[] = {"lessThan", "lessThanEqual", "greaterThan", "greaterThanEqual", "equal", "notEqual"};
  int i = static_cast<int>(op);
  if (t == Type::Float) return "(" + a + " " + scalar[i] + " " + b + ")";
  return EmitContext::call(vector[i], {a, b});
}

}  // namespace

NodeSpec compareNode() {
  NodeSpec s = math::mathNode("compare", "1 where the comparison a OP b holds, else 0 (component-wise).",
                              "out = a OP b ? 1 : 0, OP one of < <= > >= == !=");
  s.inputs = {ports::gen("a", "left operand"), ports::gen("b", 0, "right operand")};
  s.outputs = {ports::gen("out", "0 or 1 per component")};
  s.options = {comparisonOption()};
  s.parseOptions = optionParser(parseComparisonOptions);
  s.facts = math::alwaysWithin(0, 1);
  s.emit = [](EmitContext& ctx) {
    Type t = ctx.outputType(0);
    Comparison op = ctx.options<ComparisonOptions>().op;
    // float(bool) and vecN(bvecN) convert true to 1 and false to 0.
    ctx.output(0, std::string(typeName(t)) + "(" + condition(op, t, ctx.input(0), ctx.input(1)) + ")");
  };
  s.eval = [](EvalContext& ctx) {
    Comparison op = ctx.options<ComparisonOptions>().op;
    ctx.output(0, glsl::map2(ctx.input(0), ctx.input(1), ctx.outputType(0),
                             [op](double a, double b) { return holds(op, a, b) ? 1.0 : 0.0; }));
  };
  s.hardCases = {{"equal operands, less", {{"a", Value::scalar(0.5)}, {"b", Value::scalar(0.5)}}, {}, "0", 0, 0},
                 {"equal operands, less_equal", {{"a", Value::scalar(0.5)}, {"b", Value::scalar(0.5)}},
                  {{"op", "less_equal"}}, "1", 1, 1}};
  return s;
}

NodeSpec selectNode() {
  NodeSpec s = math::mathNode("select", "if_true where the comparison a OP b holds, else if_false (component-wise).",
                              "out = a OP b ? if_true : if_false, OP one of < <= > >= == !=");
  s.inputs = {ports::gen("a", "left operand of the comparison"), ports::gen("b", 0, "right operand"),
              ports::gen("if_true", 1, "the value where it holds"), ports::gen("if_false", 0, "the value where it does not")};
  s.outputs = {ports::gen("out", "the chosen value")};
  s.options = {comparisonOption()};
  s.parseOptions = optionParser(parseComparisonOptions);
  // Each component is one of the two values' components: within both ranges together (a
  // vector mixed from two unit vectors component by component need not be unit).
  s.facts = [](const std::vector<ValueFact>& in, const ParsedOptions&) {
    const ValueFact &t = in[2], &f = in[3];
    return std::vector<ValueFact>{{std::min(t.lo, f.lo), std::max(t.hi, f.hi), false}};
  };
  s.emit = [](EmitContext& ctx) {
    Type t = ctx.outputType(0);
    GlslExpr c = condition(ctx.options<ComparisonOptions>().op, t, ctx.input(0), ctx.input(1));
    // mix with a bvec selects (GLSL 1.30 on, ES 3.00): the value not chosen is never used.
    ctx.output(0, t == Type::Float ? "(" + c + " ? " + ctx.input(2) + " : " + ctx.input(3) + ")"
                                   : EmitContext::call("mix", {ctx.input(3), ctx.input(2), c}));
  };
  s.eval = [](EvalContext& ctx) {
    Comparison op = ctx.options<ComparisonOptions>().op;
    Type t = ctx.outputType(0);
    Value r = Value::ofType(t);
    auto at = [](const Value& v, int i) { return v[v.size() == 1 ? 0 : i]; };
    for (int i = 0; i < r.size(); ++i)
      r[i] = holds(op, at(ctx.input(0), i), at(ctx.input(1), i)) ? at(ctx.input(2), i) : at(ctx.input(3), i);
    ctx.output(0, r);
  };
  s.cost = "a comparison and a select per component";
  s.hardCases = {{"equal operands", {{"a", Value::scalar(2)}, {"b", Value::scalar(2)}, {"if_true", Value::scalar(5)}},
                  {{"op", "greater_equal"}}, "if_true (2 >= 2)", 5, 5}};
  return s;
}

NodeSpec inverseMixNode() {
  NodeSpec s = math::mathNode(
      "inverse_mix",
      "Where x lies between a and b (inverse lerp: 0 at a, 1 at b, unclamped); an empty range a == b gives 0.",
      "out = a == b ? 0 : (x - a) / (b - a), so that mix(a, b, out) = x");
  s.inputs = {ports::gen("a", 0, "the value that maps to 0"), ports::gen("b", 1, "the value that maps to 1"),
              ports::gen("x", "the value")};
  s.outputs = {ports::gen("out", "the fraction")};
  s.emit = [](EmitContext& ctx) {
    // A proven non-empty range (the ranges of a and b disjoint by at least FLT_MIN, so
    // b - a cannot round or flush to 0) makes the empty-range select dead.
    ValueFact a = ctx.inputFact(0), b = ctx.inputFact(1);
    const double gap = static_cast<double>(std::numeric_limits<float>::min());
    bool nonempty = b.lo - a.hi >= gap || a.lo - b.hi >= gap;
    GlslExpr x = ctx.input(2), lo = ctx.input(0), hi = ctx.input(1);
    ctx.output(0, nonempty ? "((" + x + " - " + lo + ") / (" + hi + " - " + lo + "))"
                           : EmitContext::call(math::typedName("wg_inverse_mix", ctx.outputType(0)), {lo, hi, x}));
  };
  s.eval = [](EvalContext& ctx) {
    ctx.output(0, glsl::map3(ctx.input(0), ctx.input(1), ctx.input(2), ctx.outputType(0), glsl::inverseMix));
  };
  s.cost = "two subtractions and a division per component (and a select, guarded)";
  // x - a and b - a cancel when the range is narrow against the values.
  s.conditionRoundings = 2;
  s.conditionWhy = "grows as (|x| + |a| + |b|) / |b - a| for a narrow range far from 0 (both differences cancel)";
  s.hardCases = {{"empty range", {{"a", Value::scalar(2)}, {"b", Value::scalar(2)}, {"x", Value::scalar(3)}}, {},
                  "0, not a division by zero", 0, 0},
                 {"reversed range", {{"a", Value::scalar(1)}, {"b", Value::scalar(0)}, {"x", Value::scalar(0.25)}}, {},
                  "0.75", 0.75, 0.75}};
  return s;
}

}  // namespace wg::nodes
