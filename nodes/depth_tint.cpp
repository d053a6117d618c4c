// depth_tint: shallow-to-deep colour over the water's thickness (the advanced shaders tutorial and the stylized water shader).
#include <algorithm>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"

namespace wg::nodes {

namespace {

struct DepthTintOptions {
  bool smooth;  // smoothstep rather than the linear ramp
};
DepthTintOptions parseDepthTintOptions(const OptionReader& o) { return {o.is("curve", "smooth")}; }

}  // namespace

NodeSpec depthTintNode() {
  NodeSpec s;
  s.type = "depth_tint";
  s.family = "depth and colour";
  s.summary = "Blends a shallow colour into a deep colour over the water's thickness.";
  s.formula =
      "linear (the stylized water shader): t = saturate(depth / max_depth); smooth (the advanced shaders tutorial): t = smoothstep(0, max_depth, depth); "
      "color = mix(shallow, deep, t). max_depth is floored at 1e-6; negative depth gives the shallow colour.";
  s.source = "advanced shaders tutorial (smoothstep over 10 m, shallow (0, 0.8, 0.7), deep (0, 0.1, 0.3)), stylized water shader (saturate(depth / max))";
  s.cost = "~6 ALU (linear), ~10 ALU (smooth)";
  s.inputs = {
      ports::fixed("depth", Type::Float, "water thickness in metres (e.g. from water_depth)"),
      ports::color(ports::fixed("shallow", Type::Vec3, Value::vector({0.0, 0.8, 0.7}), "colour at depth 0")),
      ports::color(ports::fixed("deep", Type::Vec3, Value::vector({0.0, 0.1, 0.3}), "colour at max_depth and below")),
      ports::fixed("max_depth", Type::Float, Value::scalar(10.0), "depth at which the deep colour is reached"),
  };
  s.outputs = {ports::fixed("color", Type::Vec3, "the tinted colour"),
               ports::fixed("factor", Type::Float, "the blend factor t in [0, 1]")};
  s.options = {ports::choice("curve", {"linear", "smooth"}, "linear", "linear ramp (the stylized water shader) or smoothstep (the advanced shaders tutorial)")};
  s.parseOptions = optionParser(parseDepthTintOptions);
  s.emit = [](EmitContext& ctx) {
    bool smooth = ctx.options<DepthTintOptions>().smooth;
    GlslExpr t = ctx.temporary(
        Type::Float, EmitContext::call(smooth                                     ? "wg_depth_tint_smooth"
                                       : ctx.inputFact("max_depth").atLeast(1e-6) ? "wg_depth_tint_linear_floored"
                                                                                  : "wg_depth_tint_linear",
                                       {ctx.input("depth"), ctx.input("max_depth")}));
    ctx.output(0, EmitContext::call("mix", {ctx.input("shallow"), ctx.input("deep"), t}));
    ctx.output(1, t);
  };
  s.eval = [](EvalContext& ctx) {
    double depth = ctx.scalar("depth"), maxDepth = std::max(ctx.scalar("max_depth"), 1e-6);
    bool smooth = ctx.options<DepthTintOptions>().smooth;
    double t = smooth ? glsl::safeSmoothstep(0.0, maxDepth, depth) : glsl::saturate(depth / maxDepth);
    ctx.output(0, glsl::map2(ctx.input("shallow"), ctx.input("deep"), Type::Vec3,
                             [t](double a, double b) { return glsl::mix(a, b, t); }));
    ctx.output(1, Value::scalar(t));
  };
  s.tolerance = 2e-6;
  s.hardCases = {
      {"negative thickness", {{"depth", Value::scalar(-3)}}, {}, "the shallow colour, t = 0", 0, 1},
      {"zero max depth", {{"depth", Value::scalar(1)}, {"max_depth", Value::scalar(0)}}, {}, "the deep colour, finite", 0, 1},
      {"sky depth (huge)", {{"depth", Value::scalar(3e38)}}, {{"curve", "smooth"}}, "the deep colour", 0, 1},
  };
  return s;
}

}  // namespace wg::nodes
