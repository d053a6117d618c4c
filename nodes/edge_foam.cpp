// edge_foam: foam where the water meets geometry (the advanced shaders tutorial and the stylized water shader): a depth mask times
// a two-layer scrolling foam texture, cut off at a threshold.
#include <algorithm>
#include <cmath>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/foam_caustics_reference.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"

namespace wg::nodes {
namespace {

// The stylized water shader: layer 1 scrolls by t speed (1, 0.5), layer 2 by t speed (-0.5, 1), at
// 0.1 and 0.08 texture repeats per metre times foam_scale.
constexpr double kLayer1Scale = 0.1, kLayer2Scale = 0.08;

}  // namespace

// The depth mask and the cut-off foam, as in nodes/glsl/edge_foam.glsl.
double edgeFoamMask(bool smooth, double depth, double width) {
  return smooth ? 1.0 - glsl::safeSmoothstep(0.0, std::max(width, 0.0), depth)
                : 1.0 - glsl::saturate(depth / std::max(width, 1e-6));
}
double edgeFoamCut(double tex, double mask, double cutoff, double softness, double strength) {
  return glsl::saturate(strength * glsl::safeSmoothstep(cutoff, cutoff + std::max(softness, 0.0), tex * mask));
}

namespace {

struct EdgeFoamOptions {
  bool smoothMask;
  double speed;
};
EdgeFoamOptions parseEdgeFoamOptions(const OptionReader& o) { return {o.is("mask", "smooth"), o.number("speed")}; }

}  // namespace

NodeSpec edgeFoamNode() {
  NodeSpec s;
  s.type = "edge_foam";
  s.family = "foam";
  s.summary = "Foam along shores and objects: shallow-depth mask times a two-layer scrolling foam texture, cut off.";
  s.formula =
      "uv1 = xz * foam_scale * 0.1 + mod(t speed (1, 0.5), 1), uv2 = xz * foam_scale * 0.08 + mod(t speed (-0.5, 1), 1); "
      "tex = (foam(uv1).r + foam(uv2).r) / 2; mask = 1 - smoothstep(0, width, depth) (smooth, the advanced shaders tutorial) or "
      "1 - saturate(depth / width) (linear, the stylized water shader); foam = saturate(strength * smoothstep(cutoff, cutoff + softness, "
      "tex * mask)); softness 0 is the stylized water shader's step(cutoff, tex * mask).";
  s.source = "advanced shaders tutorial (1 - smoothstep(0, 0.5, depth)), stylized water shader (section 9: two foam layers, step(cutoff, texture * mask) * strength)";
  s.cost = "2 texture samples + ~20 ALU; the scroll offsets are two time-phase uniforms";
  OptionSpec tex = ports::texture("texture", "builtin:foam", "the foam texture (red channel): builtin:foam or a .png path relative to the graph");
  s.options = {
      tex,
      ports::choice("mask", {"smooth", "linear"}, "smooth",
                    "depth falloff: 1 - smoothstep(0, width, depth) (the advanced shaders tutorial) or 1 - saturate(depth / width) (the stylized water shader)"),
      ports::number("speed", 0.05, -10.0, 10.0,
                    "scroll speed in texture repeats per second (compile-time, so the scroll is a double-precision "
                    "time phase, exact at t = 1e6 s)"),
  };
  s.inputs = {
      ports::fixed("depth", Type::Float, "water thickness in metres (e.g. from water_depth); <= 0 is the edge"),
      ports::fromBuiltin("position", Type::Vec3, Builtin::WorldPosition,
                         "world point (x and z place the foam texture; default: the surface position)"),
      ports::fixed("cutoff", Type::Float, Value::scalar(0.25),
                   "texture * mask level where foam starts; keep it > 0 (at 0 the step also fires on deep water)"),
      ports::fixed("width", Type::Float, Value::scalar(0.5), "depth in metres over which the foam fades out (the advanced shaders tutorial: 0.5)"),
      ports::fixed("softness", Type::Float, Value::scalar(0.0), "width of the cut-off's smooth edge; 0 = hard step (the stylized water shader)"),
      ports::fixed("strength", Type::Float, Value::scalar(1.0), "foam brightness (result clamped to [0, 1])"),
      ports::fixed("foam_scale", Type::Float, Value::scalar(1.0), "foam texture scale (the stylized water shader's _FoamScale)"),
  };
  s.outputs = {ports::fixed("foam", Type::Float, "foam amount in [0, 1]")};
  s.bypass = {{"foam", "", Value::scalar(0)}};
  s.isSource = true;  // samples a texture, reads time phases
  s.parseOptions = optionParser(parseEdgeFoamOptions);
  s.emit = [](EmitContext& ctx) {
    const auto& [smooth, speed] = ctx.options<EdgeFoamOptions>();
    // mod(speed t, 1) = mod(2 pi speed t, 2 pi) / 2 pi, and the same at half the speed.
    GlslExpr off = "vec2(0.0)";
    if (speed != 0.0) {
      GlslExpr p1 = ctx.timePhase(glsl::kTau * speed);  // one call per statement: a stable emission order
      GlslExpr p2 = ctx.timePhase(0.5 * glsl::kTau * speed);
      off = "vec2(" + p1 + ", " + p2 + ") * " + ctx.literal(1.0 / glsl::kTau);
    }
    off = ctx.temporary(Type::Vec2, off);
    GlslExpr position = ctx.input("position");
    GlslExpr foamScale = ctx.input("foam_scale");
    GlslExpr xz = ctx.temporary(Type::Vec2, position + ".xz * " + foamScale);
    GlslExpr uv1 = xz + " * " + ctx.literal(kLayer1Scale) + " + " + off;
    GlslExpr uv2 = xz + " * " + ctx.literal(kLayer2Scale) + " + vec2(-" + off + ".y, " + off + ".x)";
    GlslExpr layer1 = ctx.sampleTexture("texture", uv1);  // one look-up per statement: in the order of the text
    GlslExpr layer2 = ctx.sampleTexture("texture", uv2);
    GlslExpr t = ctx.temporary(Type::Float, "0.5 * (" + layer1 + ".r + " + layer2 + ".r)");
    GlslExpr mask = EmitContext::call(smooth ? "wg_edge_foam_mask_smooth" : "wg_edge_foam_mask_linear",
                                         {ctx.input("depth"), ctx.input("width")});
    ctx.output(0, EmitContext::call("wg_edge_foam", {t, mask, ctx.input("cutoff"), ctx.input("softness"), ctx.input("strength")}));
  };
  s.eval = [](EvalContext& ctx) {
    const auto& [smooth, speed] = ctx.options<EdgeFoamOptions>();
    double t = ctx.environment().time[0];
    double ox = 0, oy = 0;
    if (speed != 0.0) {
      ox = glsl::mod(glsl::kTau * speed * t, glsl::kTau) * (1.0 / glsl::kTau);
      oy = glsl::mod(0.5 * glsl::kTau * speed * t, glsl::kTau) * (1.0 / glsl::kTau);
    }
    const Value& pos = ctx.input("position");
    double k = ctx.scalar("foam_scale"), x = pos[0] * k, z = pos[2] * k;
    double a = ctx.sampleTexture("texture", x * kLayer1Scale + ox, z * kLayer1Scale + oy)[0];
    double b = ctx.sampleTexture("texture", x * kLayer2Scale - oy, z * kLayer2Scale + ox)[0];
    double tex = 0.5 * (a + b);
    double mask = edgeFoamMask(smooth, ctx.scalar("depth"), ctx.scalar("width"));
    ctx.output(0, Value::scalar(edgeFoamCut(tex, mask, ctx.scalar("cutoff"), ctx.scalar("softness"), ctx.scalar("strength"))));
  };
  // Bilinear filtering on the GPU (8-bit weights) moves tex by ~1/512; with softness 0 the
  // hard step can flip there, so per-pixel agreement is only guaranteed for softness > 0.
  s.tolerance = 1e-2;
  s.hardCases = {
      {"equal cutoff edges (softness 0)", {{"depth", Value::scalar(0.1)}, {"softness", Value::scalar(0)}}, {},
       "a step: 0 or 1", 0, 1},
      {"zero width", {{"depth", Value::scalar(0.0)}, {"width", Value::scalar(0)}}, {{"mask", "smooth"}},
       "equal mask edges: a step at depth 0, in [0, 1]", 0, 1},
      {"zero width, linear", {{"depth", Value::scalar(0.2)}, {"width", Value::scalar(0)}}, {{"mask", "linear"}},
       "no division by zero: no foam", 0, 0},
      {"negative thickness", {{"depth", Value::scalar(-3)}, {"softness", Value::scalar(0.1)}}, {}, "the edge: in [0, 1]", 0, 1},
      {"sky depth", {{"depth", Value::scalar(3e38)}}, {{"mask", "linear"}}, "no foam", 0, 0},
      {"huge strength", {{"depth", Value::scalar(0)}, {"strength", Value::scalar(1e30)}}, {}, "clamped to [0, 1]", 0, 1},
  };
  return s;
}

}  // namespace wg::nodes
