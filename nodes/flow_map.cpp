// flow_map: a texture dragged along a flow field in two phases half a cycle apart,
// cross-faded by triangle-wave weights so neither phase's reset shows (the stylized water shader).
#include <cmath>

#include "core/derive.h"
#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"
#include "nodes/waves_common.h"

namespace wg::nodes {

namespace {

struct FlowMapOptions {
  bool flowFromTexture;  // else from the `flow` input
};
FlowMapOptions parseFlowMapOptions(const OptionReader& o) { return {o.is("flow_source", "texture")}; }

}  // namespace

NodeSpec flowMapNode() {
  NodeSpec s;
  s.type = "flow_map";
  s.family = "flow";
  s.summary = "Flow-map animation: two phases of a texture dragged along a flow vector, blended by triangle waves.";
  s.formula =
      "flow = flow_texture(uv).xy * 2 - 1 (flow_source = texture) or the `flow` input; p_a = fract(time * speed), "
      "p_b = fract(p_a + 0.5) (= fract(time * speed + 0.5), formed from p_a so it keeps its fraction past time * speed "
      "= 2^23); w = 1 - |1 - 2 p| (so w_a + w_b = 1); uv_i = uv - flow * strength * p_i; "
      "sample = texture(uv_a) w_a + texture(uv_b) w_b.";
  s.source =
      "stylized water shader (flow maps: progress = frac(time) and frac(time + 0.5), UV = uv - flowVector * progress, "
      "weight = 1 - abs(1 - 2 progress))";
  s.cost = "two texture fetches (three with a flow texture), ~14 ALU";
  s.inputs = {
      ports::fromBuiltin("uv", Type::Vec2, Builtin::Uv, "texture coordinate"),
      ports::fromBuiltin("time", Type::Float, Builtin::Time, "seconds"),
      ports::fixed("flow", Type::Vec2, Value::vector({0, 0}), "the flow vector when flow_source = input"),
      ports::fixed("speed", Type::Float, Value::scalar(1.0), "phase cycles per second (source: 1)"),
      ports::fixed("strength", Type::Float, Value::scalar(1.0), "texture units the flow moves the texture per cycle"),
  };
  s.inputs.push_back(ports::derived("progress_a", Type::Float, "phase A's progress fract(time * speed)"));
  s.inputs.push_back(ports::derived("progress_b", Type::Float, "phase B's progress fract(progress_a + 0.5)"));
  s.inputs.push_back(ports::derived("fade_a", Type::Float, "phase A's weight 1 - |1 - 2 progress_a|"));
  s.inputs.push_back(ports::derived("fade_b", Type::Float, "phase B's weight 1 - |1 - 2 progress_b|"));
  s.outputs = {ports::fixed("sample", Type::Vec4, "the blended texture sample"),
               ports::fixed("weight_a", Type::Float, "weight of phase A, in [0, 1]"),
               ports::fixed("weight_b", Type::Float, "weight of phase B, 1 - weight_a")};
  s.options = {
      ports::texture("texture", "builtin:water_normal", "the texture dragged by the flow (normal or colour map)"),
      ports::choice("flow_source", {"texture", "input"}, "texture", "where the flow vector comes from"),
      ports::texture("flow_texture", "builtin:dudv",
                           "the flow map (flow = rg * 2 - 1), sampled at uv, when flow_source = texture"),
  };
  s.isSource = true;
  s.parseOptions = optionParser(parseFlowMapOptions);
  // The phases and their weights are the same for every pixel of a draw: ops of their own,
  // each the math node of the GLSL it replaces (fract(t * speed + offset), 1 - |1 - 2 p|).
  s.derive = [](DeriveContext& ctx) {
    ValueRef cycles = ctx.op("mul", {ctx.input("time"), ctx.input("speed")});
    auto weight = [&](const ValueRef& p) {
      ValueRef twice = ctx.op("mul", {ValueRef::constant_(Value::scalar(2.0)), p});
      return ctx.op("one_minus", {ctx.op("abs", {ctx.op("one_minus", {twice})})});
    };
    ValueRef pa = ctx.op("fract", {cycles});
    // fract(p_a + 0.5), not fract(t * speed + 0.5): past t * speed = 2^23 float32 rounds
    // t * speed + 0.5 to an even integer, both phases were 0 and both weights 0 (a black
    // sample); from p_a in [0, 1) the sum keeps its fraction bits.
    ValueRef pb = ctx.op("fract", {ctx.op("add", {pa, ValueRef::constant_(Value::scalar(0.5))})});
    ctx.set("progress_a", pa);
    ctx.set("progress_b", pb);
    ctx.set("fade_a", weight(pa));
    ctx.set("fade_b", weight(pb));
  };
  s.emit = [](EmitContext& ctx) {
    ctx.reserveTexture("texture");  // declared before flow_texture, which it samples after it
    GlslExpr uv = ctx.temporary(Type::Vec2, ctx.input("uv"));
    GlslExpr flow = ctx.options<FlowMapOptions>().flowFromTexture
                           ? EmitContext::call("wg_flow_map_decode", {ctx.sampleTexture("flow_texture", uv)})
                           : ctx.input("flow");
    GlslExpr drag = ctx.temporary(Type::Vec2, "(" + flow + ") * " + ctx.input("strength"));
    GlslExpr pa = ctx.input("progress_a"), pb = ctx.input("progress_b");
    GlslExpr wa = ctx.input("fade_a"), wb = ctx.input("fade_b");
    GlslExpr a = ctx.sampleTexture("texture", uv + " - " + drag + " * " + pa);  // in the order of the text
    GlslExpr b = ctx.sampleTexture("texture", uv + " - " + drag + " * " + pb);
    ctx.output(0, "(" + a + " * " + wa + " + " + b + " * " + wb + ")");
    ctx.output(1, wa);
    ctx.output(2, wb);
  };
  s.eval = [](EvalContext& ctx) {
    const Value& uv = ctx.input("uv");
    double fx, fy;
    if (ctx.options<FlowMapOptions>().flowFromTexture) {
      Value f = ctx.sampleTexture("flow_texture", uv[0], uv[1]);
      fx = f[0] * 2.0 - 1.0;
      fy = f[1] * 2.0 - 1.0;
    } else {
      fx = ctx.input("flow")[0];
      fy = ctx.input("flow")[1];
    }
    double k = ctx.scalar("strength");
    fx *= k;
    fy *= k;
    double pa = ctx.scalar("progress_a"), pb = ctx.scalar("progress_b");
    double wa = ctx.scalar("fade_a"), wb = ctx.scalar("fade_b");
    Value a = ctx.sampleTexture("texture", uv[0] - fx * pa, uv[1] - fy * pa);
    Value b = ctx.sampleTexture("texture", uv[0] - fx * pb, uv[1] - fy * pb);
    Value out = Value::ofType(Type::Vec4);
    for (int c = 0; c < 4; ++c) out[c] = a[c] * wa + b[c] * wb;
    ctx.output(0, out);
    ctx.output(1, Value::scalar(wa));
    ctx.output(2, Value::scalar(wb));
  };
  // fract(time * speed) in float32 at t = 524288 s: ~1e-3 of a cycle.
  // GL_LINEAR on 8-bit textures: hardware filter weights have 8 bits (llvmpipe), so one
  // sample differs from exact bilinear by up to 1/255 and two blended phases by 2/255.
  s.tolerance = 1e-2;
  s.conditionRoundings = 4;
  s.conditionWhy = "grows with the scrolled coordinates uv + t v (float32 uv and time inputs of 1e4 and more)";
  s.hardCases = {
      {"time 524288 s",
       {{"time", Value::scalar(524288)}},
       {},
       "finite, a convex blend of texels in [0, 1]",
       0,
       1,
       "sample"},
      {"time 13107 s", {{"time", Value::scalar(13107)}}, {}, "finite, in [0, 1]", 0, 1, "sample"},
      {"huge flow from the input",
       {{"flow", Value::vector({1e4, -1e4})}},
       {{"flow_source", "input"}},
       "finite: the texture repeats",
       0,
       1,
       "sample"},
      {"time 1e7 s, past 2^23 cycles: weight_b = 1",
       {{"time", Value::scalar(1e7)}},
       {},
       "weight_a 0, weight_b 1 (float32 rounds time * speed + 0.5 to an even integer: both weights were 0)",
       1,
       1,
       "weight_b"},
      {"phase reset (time 0): weight_a = 0",
       {{"time", Value::scalar(0)}},
       {},
       "weight_a 0, weight_b 1",
       0,
       0,
       "weight_a"},
  };
  return s;
}

}  // namespace wg::nodes
