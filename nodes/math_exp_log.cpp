// The exponential vocabulary: exp, exp2, log, log2, sqrt and inversesqrt, component-wise
// on float/vec2/vec3/vec4. Each emits the library's guarded form
// (nodes/glsl/math_exp_log.glsl), finite for every finite input, or the raw built-in
// where the input's value facts prove the guard dead (a log of a value >= FLT_MIN).
#include <cmath>

#include "nodes/eval_math.h"
#include "nodes/math_builders.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"

namespace wg::nodes {

using math::alwaysWithin;
using math::guardedUnary;
using math::hardX;

namespace {
// The smallest normal float: a fact x >= it makes the log/inversesqrt floor dead (bounds
// are as the shader sees them, denormals widened, so no flushed value hides below it).
constexpr double kFloatMin = glsl::kFloatMin;
}  // namespace

NodeSpec expNode() {
  NodeSpec s = guardedUnary(
      "exp", "exp", "wg_safe_exp", "e^x; x above 88 gives e^88 = 1.65e38 (the raw built-in overflows to +inf past 88.7).",
      "out = exp(min(x, 88))", [](const ValueFact& x) { return x.hi <= glsl::kExpArgMax; }, glsl::safeExp);
  s.facts = alwaysWithin(0, INFINITY);
  s.cost = "an exp2 and a multiply per component (and a min, guarded)";
  // The GPU forms exp2(x log2(e)): the product's rounding is a relative error |x| 2^-24
  // in the result, exactly the conditioning of e^x (x d/dx e^x / e^x = x). At the cap
  // x = 88 the clamp leaves no input conditioning, so the tolerance holds that rounding:
  // 88 * 2^-24 = 5.2e-6 relative (llvmpipe: 3.5e-6 at x = 84).
  s.tolerance = 6e-6;
  s.conditionRoundings = 2;
  s.conditionWhy = "relative error grows as |x| 2^-24 (the condition number of e^x is |x|)";
  s.hardCases = {hardX("exp(100)", 100, "e^88 = 1.65e38, not +inf", 1.6e38, 1.7e38),
                 hardX("exp(-100)", -100, "3.7e-44 (0 on a GPU that flushes denormals)", 0, 1e-40)};
  return s;
}

NodeSpec exp2Node() {
  NodeSpec s = guardedUnary(
      "exp2", "exp2", "wg_safe_exp2", "2^x; x above 127 gives 2^127 = 1.70e38 (the raw built-in overflows to +inf at 128).",
      "out = exp2(min(x, 127))", [](const ValueFact& x) { return x.hi <= glsl::kExp2ArgMax; }, glsl::safeExp2);
  s.facts = alwaysWithin(0, INFINITY);
  s.cost = "one exp2 per component (and a min, guarded)";
  s.tolerance = 1e-6;  // 1.6e-7 at most on llvmpipe over [-30, 30]
  s.conditionRoundings = 1;
  s.conditionWhy = "relative error grows as |x| ln(2) 2^-24 (the condition number of 2^x)";
  s.hardCases = {hardX("exp2(200)", 200, "2^127 = 1.70e38, not +inf", 1.7e38, 1.71e38)};
  return s;
}

NodeSpec logNode() {
  NodeSpec s = guardedUnary(
      "log", "log", "wg_safe_log",
      "Natural logarithm; x <= 0 gives log(2^-126) = -87.34 (the raw built-in gives -inf at 0 and is undefined below).",
      "out = log(max(x, 2^-126))", [](const ValueFact& x) { return x.atLeast(kFloatMin); }, glsl::safeLog);
  s.cost = "a log2 and a multiply per component (and a max, guarded)";
  // Absolute error: log x near x = 1 is near 0, and the GPU's log2 keeps ~1e-7 absolute.
  s.tolerance = 1e-6;
  s.hardCases = {hardX("log(0)", 0, "-87.34, not -inf", -87.34, -87.33),
                 hardX("log(-1)", -1, "-87.34, not NaN", -87.34, -87.33)};
  return s;
}

NodeSpec log2Node() {
  NodeSpec s = guardedUnary(
      "log2", "log2", "wg_safe_log2",
      "Base-2 logarithm; x <= 0 gives -126 (the raw built-in gives -inf at 0 and is undefined below).",
      "out = log2(max(x, 2^-126))", [](const ValueFact& x) { return x.atLeast(kFloatMin); }, glsl::safeLog2);
  s.cost = "one log2 per component (and a max, guarded)";
  s.tolerance = 1e-6;
  s.hardCases = {hardX("log2(0)", 0, "-126, not -inf", -126, -126), hardX("log2(-5)", -5, "-126, not NaN", -126, -126)};
  return s;
}

NodeSpec sqrtNode() {
  NodeSpec s = guardedUnary("sqrt", "sqrt", "wg_safe_sqrt",
                            "Square root; x < 0 gives 0 (the raw built-in is undefined there: NaN).",
                            "out = sqrt(max(x, 0))", [](const ValueFact& x) { return x.atLeast(0); }, glsl::safeSqrt);
  s.facts = alwaysWithin(0, INFINITY);
  s.cost = "one sqrt per component (and a max, guarded)";
  // Well-conditioned (relative condition 1/2) except at 0, where float inputs are exact.
  s.tolerance = 1e-6;
  s.hardCases = {hardX("sqrt(-1)", -1, "0, not NaN", 0, 0), hardX("sqrt(-1e-7)", -1e-7, "0 (a rounded-below-zero square)", 0, 0)};
  return s;
}

NodeSpec inversesqrtNode() {
  NodeSpec s = guardedUnary(
      "inversesqrt", "inversesqrt", "wg_safe_inversesqrt",
      "1 / sqrt(x); x <= 0 gives 2^63 = 9.22e18 (the raw built-in gives +inf at 0 and is undefined below).",
      "out = inversesqrt(max(x, 2^-126))", [](const ValueFact& x) { return x.atLeast(kFloatMin); }, glsl::safeInverseSqrt);
  s.facts = alwaysWithin(0, INFINITY);
  s.cost = "one rsqrt per component (and a max, guarded)";
  s.tolerance = 1e-6;
  s.hardCases = {hardX("inversesqrt(0)", 0, "2^63 = 9.22e18, not +inf", 9.2e18, 9.3e18),
                 hardX("inversesqrt(-4)", -4, "2^63, not NaN", 9.2e18, 9.3e18)};
  return s;
}

}  // namespace wg::nodes
