// near_far_ratio: the per-draw part of a depth linearisation. linearize_depth and
// water_depth derive their near plane and near/far ratio from it (NodeSpec::derive), so
// the division n / max(f, n) that used to run per pixel, once per linearisation, is an op
// of its own that the frequency analysis classifies per-draw.
#include <algorithm>

#include "core/emit_context.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"
#include "nodes/shading_reference.h"

namespace wg::nodes {

NodeSpec nearFarRatioNode() {
  NodeSpec s;
  s.type = "near_far_ratio";
  s.family = "depth and colour";
  s.summary = "The near plane (floored at 1e-6) and the ratio near / far of a perspective projection: what a depth "
              "linearisation needs that is the same for every pixel.";
  s.formula =
      "near = max(n, 1e-6); ratio = near / max(f, near), in [0, 1] (f = inf gives 0; f < n is raised to n, "
      "giving 1). linearize_depth is then near / ((1 - d) + d ratio).";
  s.source = "advanced shaders tutorial (linearizeDepth, part 9), rewritten as in linearize_depth";
  s.cost = "one division, two max; the same for every pixel of a draw";
  s.inputs = {ports::fromBuiltin("near_far", Type::Vec2, Builtin::CameraNearFar,
                                 "the projection's near and far planes; far may be inf or 1e38")};
  s.outputs = {ports::fixed("near", Type::Float, "the near plane, at least 1e-6"),
               ports::fixed("ratio", Type::Float, "near / far (far raised to near), in [0, 1]")};
  s.facts = [](const std::vector<ValueFact>& in, const ParsedOptions&) {
    const ValueFact& nf = in[0];  // one range for both components
    ValueFact nearPlane{std::max(nf.lo, 1e-6), std::max(nf.hi, 1e-6), false};
    return std::vector<ValueFact>{nearPlane, ValueFact{0, 1, false}};
  };
  s.emit = [](EmitContext& ctx) {
    GlslExpr nf = ctx.temporary(Type::Vec2, ctx.input("near_far"));
    // Where the facts prove near >= 1e-6 (the runtime's clamped u_camera_near_far), the
    // floor is dead: near itself, as wg_linearize_depth_known reads it.
    GlslExpr n = ctx.inputFact("near_far").atLeast(1e-6) ? nf + ".x"
                                                             : EmitContext::call("wg_near_far_floor", {nf});
    n = ctx.temporary(Type::Float, n);
    ctx.output(0, n);
    ctx.output(1, EmitContext::call("wg_near_far_ratio", {n, nf + ".y"}));
  };
  s.eval = [](EvalContext& ctx) {
    const Value& nf = ctx.input("near_far");
    NearFarRatio r = nearFarRatioReference(nf[0], nf[1]);
    ctx.output(0, Value::scalar(r.nearPlane));
    ctx.output(1, Value::scalar(r.ratio));
  };
  s.tolerance = 1e-6;  // one rounded division
  s.hardCases = {
      {"near -> 0", {{"near_far", Value::vector({0, 100})}}, {}, "near floored at 1e-6", 0, 2e-6, "near"},
      {"far < near", {{"near_far", Value::vector({1, 0.5})}}, {}, "far raised to near: ratio 1", 1, 1, "ratio"},
      {"zero far plane", {{"near_far", Value::vector({0.1, 0})}}, {}, "far raised to near: ratio 1, finite", 1, 1, "ratio"},
  };
  return s;
}

}  // namespace wg::nodes
