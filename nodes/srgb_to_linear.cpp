// srgb_to_linear: the sRGB transfer function decoding a colour authored as sRGB values (what
// a colour picker shows) to the linear values lighting works in. Resolve inserts it after
// every read of a colour parameter and uses its reference to linearise colour literals
// (core/color_parameters.h); a graph may use it too. The curve is the one sRGB textures are
// decoded with (core/color_space.h), extended past [0, 1].
#include <cmath>

#include "core/color_space.h"
#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/math_builders.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"

namespace wg::nodes {

NodeSpec srgbToLinearNode() {
  NodeSpec s = math::mathNode(
      "srgb_to_linear",
      "Decodes an sRGB-authored colour (the values a colour picker shows) to linear; a vec4's alpha passes through.",
      "out = x / 12.92 for |x| <= 0.04045, else ((|x| + 0.055) / 1.055)^2.4, with the sign of x (IEC 61966-2-1, "
      "mirrored for negative x, continued past 1 for HDR colours); per component, a vec4's w unchanged");
  s.family = "depth and colour";
  s.cost = "a guarded pow (log2, exp2) and a select per colour component";
  s.inputs = {ports::gen("x", "a colour in sRGB terms (float, vec3; vec4 with linear alpha)")};
  s.outputs = {ports::gen("out", "the colour in linear terms")};
  s.emit = [](EmitContext& ctx) {
    ctx.output(0, EmitContext::call(math::typedName("wg_srgb_to_linear", ctx.outputType(0)), {ctx.input(0)}));
  };
  s.eval = [](EvalContext& ctx) { ctx.output(0, srgbToLinear(ctx.input(0))); };
  // Monotonic, odd, [0, 1] into [0, 1] and [-1, 1] into [-1, 1] (also alpha, which passes).
  s.facts = [](const std::vector<ValueFact>& in, const ParsedOptions&) {
    const ValueFact& x = in.at(0);
    ValueFact out;
    out.lo = x.lo >= 0 ? 0.0 : x.lo >= -1 ? -1.0 : -INFINITY;
    out.hi = x.hi <= 0 ? 0.0 : x.hi <= 1 ? 1.0 : INFINITY;
    return std::vector<ValueFact>{out};
  };
  // The GPU's log2/exp2 pow: a few ulp relative; the input's rounding moves the result by
  // 2.4 times its relative error (the exponent), the condition number of the power segment.
  s.tolerance = 4e-6;
  s.conditionRoundings = 1;
  s.conditionWhy = "relative error of the power segment is 2.4 times the input's (the exponent)";
  using math::hardX;
  s.hardCases = {
      hardX("zero", 0, "0 (black stays black)", 0, 0),
      hardX("knee", 0.04045, "0.04045 / 12.92 = 0.0031308 (the segments meet here)", 0.00313, 0.003132),
      hardX("below the knee", 0.04, "0.04 / 12.92 = 0.0030960 (linear segment)", 0.003095, 0.003097),
      hardX("above the knee", 0.041, "((0.041 + 0.055) / 1.055)^2.4 = 0.0031734 (power segment)", 0.003172, 0.003175),
      hardX("one", 1, "1 (white stays white, never above)", 0.999998, 1),
      hardX("negative", -0.5, "-0.21404: the curve mirrored, finite (no pow of a negative base)", -0.21405, -0.21403),
      hardX("HDR 4", 4, "((4 + 0.055) / 1.055)^2.4 = 25.3: the power segment continued past 1", 25.2, 25.4),
      hardX("huge", 1e30, "2^127 = 1.70e38: capped like the guarded pow, not +inf", 1.7e38, 1.71e38),
      hardX("huge negative", -1e30, "-2^127, finite", -1.71e38, -1.7e38),
  };
  return s;
}

}  // namespace wg::nodes
