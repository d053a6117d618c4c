// The rounding vocabulary: fract, floor, ceil, round, trunc, mod, step, sign, negate and
// one_minus, component-wise on float/vec2/vec3/vec4. All are GLSL built-ins or operators,
// exact on float inputs (no input roundings: the GPU rounds nothing a float input does
// not already carry); only mod, whose quotient can overflow, has a guarded form
// (nodes/glsl/math_rounding.glsl).
#include <cmath>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/math_builders.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"

namespace wg::nodes {

using math::alwaysWithin;
using math::hardX;
using math::typedName;
using math::unaryFunction;

NodeSpec fractNode() {
  NodeSpec s = unaryFunction("fract", "fract", "Fractional part, x - floor(x), in [0, 1].", "out = x - floor(x)",
                             [](double x) { return glsl::fract(x); });
  // float rounding can make x - floor(x) exactly 1 (fract(-1e-8) = 1 - 1e-8 rounds up).
  s.facts = alwaysWithin(0, 1);
  s.hardCases = {hardX("tiny negative", -1e-8, "1 - 1e-8, which float rounds to 1: in [0, 1]", 0, 1),
                 hardX("huge", 1e30, "0 (every float this large is an integer)", 0, 0),
                 hardX("negative half", -2.5, "0.5 (floor goes towards -inf)", 0.5, 0.5)};
  return s;
}

NodeSpec floorNode() {
  NodeSpec s = unaryFunction("floor", "floor", "Largest integer not above x.", "out = floor(x)",
                             [](double x) { return std::floor(x); });
  s.hardCases = {hardX("negative half", -2.5, "-3", -3, -3), hardX("huge", -1e30, "itself", -1e30, -1e30)};
  return s;
}

NodeSpec ceilNode() {
  NodeSpec s = unaryFunction("ceil", "ceil", "Smallest integer not below x.", "out = ceil(x)",
                             [](double x) { return std::ceil(x); });
  s.hardCases = {hardX("negative half", -2.5, "-2", -2, -2), hardX("huge", 1e30, "itself", 1e30, 1e30)};
  return s;
}

NodeSpec roundNode() {
  // GLSL's round leaves the direction of a half to the implementation, so GPU and CPU
  // could disagree by 1 at every half; roundEven is defined everywhere.
  NodeSpec s = unaryFunction("round", "roundEven",
                             "Nearest integer; halves go to the even one (GLSL's roundEven: GLSL's round leaves the "
                             "direction of a half to the implementation).",
                             "out = roundEven(x): 0.5 -> 0, 1.5 -> 2, -2.5 -> -2", [](double x) { return glsl::roundEven(x); });
  s.hardCases = {hardX("half to even below", 2.5, "2", 2, 2), hardX("half to even above", 3.5, "4", 4, 4),
                 hardX("negative half", -0.5, "0 (or -0)", 0, 0)};
  return s;
}

NodeSpec truncNode() {
  NodeSpec s = unaryFunction("trunc", "trunc", "Integer part, rounding towards zero.", "out = trunc(x) = sign(x) floor(|x|)",
                             [](double x) { return std::trunc(x); });
  s.hardCases = {hardX("negative", -2.7, "-2", -2, -2)};
  return s;
}

NodeSpec signNode() {
  NodeSpec s = unaryFunction("sign", "sign", "-1, 0 or 1 by the sign of x.", "out = x > 0 ? 1 : (x < 0 ? -1 : 0)",
                             [](double x) { return glsl::sign(x); });
  s.facts = alwaysWithin(-1, 1);
  s.hardCases = {hardX("zero", 0, "0", 0, 0), hardX("tiny negative", -1e-30, "-1", -1, -1)};
  return s;
}

NodeSpec negateNode() {
  NodeSpec s = math::mathNode("negate", "Minus x.", "out = -x");
  s.inputs = {ports::gen("x", "the value")};
  s.outputs = {ports::gen("out", "-x")};
  // Negation is exact, so the bounds swap exactly.
  s.facts = [](const std::vector<ValueFact>& in, const ParsedOptions&) {
    return std::vector<ValueFact>{{-in[0].hi, -in[0].lo, false}};
  };
  s.emit = [](EmitContext& ctx) { ctx.output(0, "(-" + ctx.input(0) + ")"); };
  s.eval = [](EvalContext& ctx) { ctx.output(0, glsl::map1(ctx.input(0), ctx.outputType(0), [](double x) { return -x; })); };
  s.cost = "free (a source modifier)";
  return s;
}

NodeSpec oneMinusNode() {
  NodeSpec s = math::mathNode("one_minus", "1 - x: the complement of a fraction (transmittance from reflectance).",
                              "out = 1 - x");
  s.inputs = {ports::gen("x", "the value")};
  s.outputs = {ports::gen("out", "1 - x")};
  // 1 - x of a float in [0, 1] is exact (Sterbenz), so [0, 1] maps onto itself.
  s.facts = [](const std::vector<ValueFact>& in, const ParsedOptions&) {
    bool unit = in[0].atLeast(0) && in[0].hi <= 1;
    return std::vector<ValueFact>{unit ? ValueFact{0, 1, false} : ValueFact{}};
  };
  s.emit = [](EmitContext& ctx) { ctx.output(0, "(1.0 - " + ctx.input(0) + ")"); };
  s.eval = [](EvalContext& ctx) {
    ctx.output(0, glsl::map1(ctx.input(0), ctx.outputType(0), [](double x) { return 1.0 - x; }));
  };
  return s;
}

NodeSpec modNode() {
  NodeSpec s = math::mathNode(
      "mod", "GLSL's floored modulo, in [0, y) for y > 0; y = 0 gives 0 (the raw built-in gives NaN).",
      "out = x - y floor(x / y); 0 unless |x| < 1e38 |y| (y = 0, y tiny against x, or x not finite): the limit as "
      "y -> 0. The test is on x and y, not on the quotient's inf, which a driver that folds y - y to 0 loses");
  s.inputs = {ports::gen("x", "the dividend"), ports::gen("y", 1, "the divisor")};
  s.outputs = {ports::gen("out", "the remainder, with the sign of y")};
  s.emit = [](EmitContext& ctx) {
    // |y| >= 1 proven keeps |x / y| <= |x| for every finite x: the guard is dead.
    ValueFact y = ctx.inputFact(1);
    bool rawIsSafe = y.atLeast(1) || y.hi <= -1;
    std::string fn = rawIsSafe ? "mod" : typedName("wg_safe_mod", ctx.outputType(0));
    ctx.output(0, EmitContext::call(fn, {ctx.input(0), ctx.input(1)}));
  };
  s.eval = [](EvalContext& ctx) { ctx.output(0, glsl::map2(ctx.input(0), ctx.input(1), ctx.outputType(0), glsl::safeMod)); };
  s.cost = "a division, a floor and a multiply-add per component (and a select, guarded)";
  // x / y rounds: near a multiple of y the floor can flip and the result jump by y, and
  // for |x| >> |y| the result keeps only float's absolute precision of x. Both are what
  // rounding x and y by 2 ulps makes of the exact result.
  s.conditionRoundings = 2;
  s.conditionWhy = "grows at multiples of y, where x / y rounding across an integer moves the result by y, and with "
                   "|x| / |y| (float32 keeps |x| 2^-24 absolute)";
  s.hardCases = {{"mod(x, 0)", {{"x", Value::scalar(5.3)}, {"y", Value::scalar(0)}}, {}, "0, not NaN", 0, 0},
                 {"mod(0, 0)", {{"x", Value::scalar(0)}, {"y", Value::scalar(0)}}, {}, "0, not NaN", 0, 0},
                 {"quotient overflows", {{"x", Value::scalar(1e30)}, {"y", Value::scalar(1e-10)}}, {}, "0, not -inf", 0, 0},
                 {"negative dividend", {{"x", Value::scalar(-0.25)}, {"y", Value::scalar(1)}}, {}, "0.75 (floored)", 0.75, 0.75}};
  return s;
}

NodeSpec stepNode() {
  NodeSpec s = math::mathNode("step", "0 below the edge, 1 from it on.", "out = x < edge ? 0 : 1 (component-wise)");
  s.inputs = {ports::gen("edge", 0.5, "where the step is"), ports::gen("x", "the value")};
  s.outputs = {ports::gen("out", "0 or 1")};
  s.facts = alwaysWithin(0, 1);
  s.emit = [](EmitContext& ctx) { ctx.output(0, EmitContext::call("step", {ctx.input(0), ctx.input(1)})); };
  s.eval = [](EvalContext& ctx) { ctx.output(0, glsl::map2(ctx.input(0), ctx.input(1), ctx.outputType(0), glsl::step)); };
  s.hardCases = {{"x at the edge", {{"edge", Value::scalar(0.5)}, {"x", Value::scalar(0.5)}}, {}, "1 (x >= edge)", 1, 1}};
  return s;
}

}  // namespace wg::nodes
