// The trigonometric vocabulary: tan, asin, acos, atan, atan2, sinh, cosh and tanh,
// component-wise on float/vec2/vec3/vec4 (radians). Where GLSL leaves a result undefined
// or it overflows (asin of 1.0000001, atan(0, 0), sinh(100)) the library's guarded form
// (nodes/glsl/math_trig.glsl) gives a documented finite value; value facts pick the raw
// built-in where the guard is dead.
#include <cmath>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/math_builders.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"

namespace wg::nodes {

using math::guardedUnary;
using math::hardX;
using math::typedName;
using math::unaryFunction;

namespace {
constexpr double kPi = 3.14159265358979323846;
// Inside [-1, 1] the clamp of asin/acos is dead.
bool withinUnit(const ValueFact& x) { return x.atLeast(-1) && x.hi <= 1; }
bool withinHyperbolicRange(const ValueFact& x) {
  return x.atLeast(-glsl::kHyperbolicArgMax) && x.hi <= glsl::kHyperbolicArgMax;
}
}  // namespace

NodeSpec tanNode() {
  NodeSpec s = guardedUnary(
      "tan", "tan", "wg_safe_tan",
      "Tangent (radians); finite at the poles: sin / cos with |cos| floored at 1e-30, so at most 1e30 in magnitude "
      "where a GPU's cos rounds to 0 (the raw built-in gives inf there).",
      "out = sin(x) / (cos(x) < 0 ? min(cos(x), -1e-30) : max(cos(x), 1e-30))",
      // Within +-1.5 rad cos(x) >= 0.07: the floor is dead.
      [](const ValueFact& x) { return x.atLeast(-1.5) && x.hi <= 1.5; }, glsl::safeTan);
  s.cost = "a sin, a cos and a division per component (and a select, guarded)";
  // Near a pole tan moves by (1 + tan^2) per radian: float32 rounding of x there (1e-7
  // rad at pi/2) moves it by up to its own size. The input roundings bound exactly that;
  // the evaluation itself keeps 1.3e-7 relative (llvmpipe, [-10, 10]).
  s.tolerance = 1e-6;
  s.conditionRoundings = 2;
  s.conditionWhy = "grows as (1 + tan^2 x) |x| near the poles x = pi/2 + k pi, where float32 rounding of x alone can "
                   "change the sign of cos";
  s.hardCases = {hardX("tan(pi/2)", kPi / 2, "finite: float32 pi/2 lies 4.4e-8 past the pole, tan = -2.3e7", -1e30, 1e30),
                 hardX("tan(-pi/2)", -kPi / 2, "finite, +2.3e7", -1e30, 1e30), hardX("tan(0)", 0, "0", 0, 0)};
  return s;
}

NodeSpec asinNode() {
  NodeSpec s = guardedUnary("asin", "asin", "wg_safe_asin",
                            "Arcsine in [-pi/2, pi/2]; |x| > 1 is clamped to +-1 (the raw built-in is undefined there: "
                            "NaN), so a component rounded to 1.0000001 gives pi/2.",
                            "out = asin(clamp(x, -1, 1))", withinUnit, glsl::safeAsin);
  s.cost = "about 10 ALU per component (a polynomial and a sqrt on most GPUs)";
  // GPUs evaluate asin by a short polynomial, not to float precision: Mesa's llvmpipe
  // errs by up to 3.3e-4 rad (asin) and 1.3e-4 rad (acos), measured over [-1, 1] in steps
  // of 0.005; 5e-4 holds both with margin.
  s.tolerance = 5e-4;
  s.conditionRoundings = 2;
  s.conditionWhy = "grows as 1 / sqrt(1 - x^2) towards |x| = 1, where float32 rounding of x moves asin by up to 3.5e-4";
  s.hardCases = {hardX("asin(1.0000001)", 1.0000001, "pi/2, not NaN", kPi / 2, kPi / 2),
                 hardX("asin(-1.0000001)", -1.0000001, "-pi/2, not NaN", -kPi / 2, -kPi / 2)};
  return s;
}

NodeSpec acosNode() {
  NodeSpec s = guardedUnary("acos", "acos", "wg_safe_acos",
                            "Arccosine in [0, pi]; |x| > 1 is clamped to +-1 (the raw built-in is undefined there: NaN), "
                            "so a cosine rounded to 1.0000001 gives 0.",
                            "out = acos(clamp(x, -1, 1))", withinUnit, glsl::safeAcos);
  s.cost = "about 10 ALU per component (a polynomial and a sqrt on most GPUs)";
  s.tolerance = 5e-4;  // the polynomial's error, as for asin
  s.conditionRoundings = 2;
  s.conditionWhy = "grows as 1 / sqrt(1 - x^2) towards |x| = 1, where float32 rounding of x moves acos by up to 3.5e-4";
  s.hardCases = {hardX("acos(1.0000001)", 1.0000001, "0, not NaN", 0, 0),
                 hardX("acos(-1.0000001)", -1.0000001, "pi, not NaN", kPi, kPi)};
  return s;
}

NodeSpec atanNode() {
  NodeSpec s = unaryFunction("atan", "atan", "Arctangent in (-pi/2, pi/2).", "out = atan(x)",
                             [](double x) { return std::atan(x); });
  s.cost = "about 12 ALU per component (a polynomial on most GPUs)";
  s.tolerance = 1e-5;  // llvmpipe's polynomial: 3.3e-6 rad at most over [-30, 30]
  s.hardCases = {hardX("atan(1e30)", 1e30, "pi/2", kPi / 2, kPi / 2), hardX("atan(-1e30)", -1e30, "-pi/2", -kPi / 2, -kPi / 2)};
  return s;
}

NodeSpec atan2Node() {
  NodeSpec s = math::mathNode("atan2",
                              "Angle of the point (x, y) in [-pi, pi] (GLSL's atan(y, x)); the origin gives 0 (GLSL "
                              "leaves atan(0, 0) undefined), and the negative x axis pi whatever the sign of a zero y.",
                              "out = x == 0 && y == 0 ? 0 : atan(y, x)");
  s.inputs = {ports::gen("y", "the vertical component (numerator)"), ports::gen("x", 1, "the horizontal component")};
  s.outputs = {ports::gen("out", "the angle in radians")};
  s.emit = [](EmitContext& ctx) {
    // x > 0 or a sign of y proven: the point is never the origin, nor on the negative x
    // axis, where the raw built-in gives -pi for y = -0.0.
    ValueFact y = ctx.inputFact(0), x = ctx.inputFact(1);
    bool rawIsSafe = x.above(0) || y.above(0) || y.hi < 0;
    std::string fn = rawIsSafe ? "atan" : typedName("wg_safe_atan2", ctx.outputType(0));
    ctx.output(0, EmitContext::call(fn, {ctx.input(0), ctx.input(1)}));
  };
  s.eval = [](EvalContext& ctx) {
    ctx.output(0, glsl::map2(ctx.input(0), ctx.input(1), ctx.outputType(0), glsl::safeAtan2));
  };
  s.cost = "about 16 ALU per component (a polynomial, a division and quadrant selects)";
  s.tolerance = 1e-5;  // the atan polynomial: 2.1e-6 rad at most around two circles (r = 0.01, 3)
  // The angle moves by |dx| / r: rounding x and y near the origin turns it.
  s.conditionRoundings = 1;
  s.conditionWhy = "the angle's slope is 1 / r: float32 rounding of x and y moves it by about 2^-24 rad wherever the "
                   "point is (and by 2 pi across the negative x axis)";
  s.hardCases = {{"atan(0, 0)", {{"y", Value::scalar(0)}, {"x", Value::scalar(0)}}, {}, "0, not NaN", 0, 0},
                 {"negative x axis", {{"y", Value::scalar(0)}, {"x", Value::scalar(-1)}}, {}, "pi", kPi, kPi},
                 {"negative x axis, y = -0.0", {{"y", Value::scalar(-0.0)}, {"x", Value::scalar(-1)}}, {}, "pi, not -pi", kPi, kPi},
                 {"straight down", {{"y", Value::scalar(-2)}, {"x", Value::scalar(0)}}, {}, "-pi/2", -kPi / 2, -kPi / 2}};
  return s;
}

NodeSpec sinhNode() {
  NodeSpec s = guardedUnary("sinh", "sinh", "wg_safe_sinh",
                            "Hyperbolic sine; |x| above 88 gives +-sinh(88) = +-8.26e37 (the raw built-in overflows "
                            "to inf, or NaN where a driver forms e^x - e^-x).",
                            "out = sinh(clamp(x, -88, 88)) = (e^x - e^-x) / 2", withinHyperbolicRange, glsl::safeSinh);
  s.cost = "two exp2 and a few ALU per component";
  // At the cap x = 88 the clamp leaves no input conditioning, and rounding x log2(e)
  // alone is up to 88 * 2^-24 = 5.2e-6 relative (llvmpipe: 1.7e-6).
  s.tolerance = 6e-6;
  s.conditionRoundings = 2;
  s.conditionWhy = "relative error grows as |x| 2^-24 (the condition number of e^x), as for exp";
  s.hardCases = {hardX("sinh(100)", 100, "sinh(88) = 8.26e37, not inf", 8.2e37, 8.3e37),
                 hardX("sinh(-100)", -100, "-8.26e37, not -inf", -8.3e37, -8.2e37)};
  return s;
}

NodeSpec coshNode() {
  NodeSpec s = guardedUnary("cosh", "cosh", "wg_safe_cosh",
                            "Hyperbolic cosine; |x| above 88 gives cosh(88) = 8.26e37 (the raw built-in overflows to inf).",
                            "out = cosh(clamp(x, -88, 88)) = (e^x + e^-x) / 2", withinHyperbolicRange, glsl::safeCosh);
  s.cost = "two exp2 and a few ALU per component";
  // At the cap x = 88 the clamp leaves no input conditioning, and rounding x log2(e)
  // alone is up to 88 * 2^-24 = 5.2e-6 relative (llvmpipe: 1.7e-6).
  s.tolerance = 6e-6;
  s.conditionRoundings = 2;
  s.conditionWhy = "relative error grows as |x| 2^-24 (the condition number of e^x), as for exp";
  s.hardCases = {hardX("cosh(-100)", -100, "cosh(88) = 8.26e37, not inf", 8.2e37, 8.3e37)};
  return s;
}

NodeSpec tanhNode() {
  NodeSpec s = guardedUnary(
      "tanh", "tanh", "wg_safe_tanh",
      "Hyperbolic tangent in [-1, 1]; x is clamped to [-10, 10] first (tanh(10) = 1 - 4e-9, which float rounds to 1), "
      "so a driver forming (e^x - e^-x) / (e^x + e^-x) never divides inf by inf.",
      "out = tanh(clamp(x, -10, 10))",
      [](const ValueFact& x) { return x.atLeast(-glsl::kTanhArgMax) && x.hi <= glsl::kTanhArgMax; }, glsl::safeTanh);
  s.cost = "two exp2 and a division per component";
  s.tolerance = 1e-6;  // 1.4e-7 at most on llvmpipe over [-30, 30]
  s.hardCases = {hardX("tanh(100)", 100, "1, not NaN", 0.999999, 1), hardX("tanh(-1e30)", -1e30, "-1, not NaN", -1, -0.999999)};
  return s;
}

}  // namespace wg::nodes
