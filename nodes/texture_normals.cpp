// texture_normals.cpp — the texture-driven surface nodes of the waves family:
// normal_map_scroll (two scrolling normal-map layers, the advanced shaders tutorial and the stylized water shader), normal_from_height
// (central differences of a height texture, the deferred water article) and dudv_distortion (the classic WebGL water renderer).
#include <algorithm>
#include <cmath>

#include "core/derive.h"
#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"
#include "nodes/waves_common.h"

namespace wg::nodes {
namespace {

using waves::D3;

D3 unpack(const Value& texel) { return {texel[0] * 2.0 - 1.0, texel[1] * 2.0 - 1.0, texel[2] * 2.0 - 1.0}; }

D3 tangentToWorld(const D3& ts, const EvalContext& ctx) {
  D3 t = waves::d3(ctx.input("tangent")), b = waves::d3(ctx.input("binormal")), n = waves::d3(ctx.input("normal"));
  if (waves::dot(n, n) < 1e-12) n = {0, 1, 0};  // as the GLSL: a zero normal carries no direction
  return waves::unitOr(t * ts.x + b * ts.y + n * ts.z, {0, 1, 0});
}

// The tangent frame ports shared by the normal nodes: a y-up plane by default.
std::vector<PortSpec> framePorts() {
  return {ports::fromBuiltin("normal", Type::Vec3, Builtin::Normal, "the surface normal N (tangent-space z)"),
          ports::fixed("tangent", Type::Vec3, Value::vector({1, 0, 0}),
                       "tangent T (tangent-space x); +x for a y-up water plane"),
          ports::fixed("binormal", Type::Vec3, Value::vector({0, 0, 1}),
                       "binormal B (tangent-space y); +z for a y-up water plane")};
}

enum class NormalBlend { Add, Whiteout, Rnm };

struct NormalMapScrollOptions {
  NormalBlend blend;
  std::string blendFunction;  // the GLSL function of that blend
};
NormalMapScrollOptions parseNormalMapScrollOptions(const OptionReader& o) {
  return {o.choice<NormalBlend>("blend", {{"add", NormalBlend::Add}, {"whiteout", NormalBlend::Whiteout}, {"rnm", NormalBlend::Rnm}}),
          "wg_normal_map_scroll_" + o.choiceName("blend")};
}

// The blends of normal_map_scroll, in double as the GLSL computes them.
D3 normalMapBlend(NormalBlend mode, const D3& a, const D3& b) {
  if (mode == NormalBlend::Whiteout) return waves::safeNormalize({a.x + b.x, a.y + b.y, a.z * b.z});
  if (mode == NormalBlend::Rnm) {
    D3 t = a + D3{0, 0, 1};
    D3 u{-b.x, -b.y, b.z};
    return waves::safeNormalize(t * (waves::dot(t, u) / std::max(t.z, 1e-6)) - u);
  }
  return waves::safeNormalize(a + b);
}

// The scroll fract(speed * time) as ops of their own (NodeSpec::derive): the same for every
// pixel of a draw. A speed written as zero scrolls by exactly 0 (the runtime's time is
// finite), so no op computes it.
ValueRef deriveScroll(DeriveContext& ctx, const ValueRef& speed, const ValueRef& time) {
  if (speed.kind == ValueRef::Kind::Const) {
    bool zero = true;
    for (int k = 0; k < speed.constant().size(); ++k) zero = zero && speed.constant()[k] == 0;
    if (zero) return ValueRef::constant_(Value::ofType(speed.constant().type));
  }
  return ctx.op("fract", {ctx.op("mul", {speed, time})});
}

}  // namespace

NodeSpec normalMapScrollNode() {
  NodeSpec s;
  s.type = "normal_map_scroll";
  s.family = "waves";
  s.summary = "Two scrolling samples of a normal map, blended (add, whiteout or RNM) and taken to world space.";
  s.formula =
      "uv_i = uv * scale_i + fract(speed_i * time); n_i = tex(uv_i).xyz * 2 - 1; add: n = normalize(n_a + n_b) "
      "(the advanced shaders tutorial, the stylized water shader); whiteout: normalize(n_a.xy + n_b.xy, n_a.z n_b.z); rnm (reoriented normal mapping): t = n_a + "
      "(0,0,1), u = n_b (-1,-1,1), n = normalize(t dot(t, u) / t.z - u). n.xy *= strength; "
      "normal = normalize(T n.x + B n.y + N n.z) (up if degenerate).";
  s.source =
      "advanced shaders tutorial (approach 2: uv * 4 + t (0.05, 0.03), uv * 8 + t (-0.03, 0.07), normalize(n1 + n2)), "
      "stylized water shader (two layers, normalBlend.xy *= strength; mentions RNM)";
  s.cost = "two texture fetches; add ~8 ALU, whiteout ~9 ALU, rnm ~14 ALU; world transform ~10 ALU";
  s.inputs = {
      ports::fromBuiltin("uv", Type::Vec2, Builtin::Uv, "texture coordinate of the surface"),
      ports::fromBuiltin("time", Type::Float, Builtin::Time, "seconds"),
      ports::fixed("scale_a", Type::Float, Value::scalar(4.0), "tiling of the first layer"),
      ports::fixed("speed_a", Type::Vec2, Value::vector({0.05, 0.03}), "scroll of the first layer, texture units/s"),
      ports::fixed("scale_b", Type::Float, Value::scalar(8.0), "tiling of the second layer"),
      ports::fixed("speed_b", Type::Vec2, Value::vector({-0.03, 0.07}), "scroll of the second layer, texture units/s"),
      ports::fixed("strength", Type::Float, Value::scalar(1.0), "multiplies the blended normal's slope (xy)"),
  };
  for (auto& p : framePorts()) s.inputs.push_back(p);
  s.inputs.push_back(ports::derived("scroll_a", Type::Vec2, "the first layer's scroll fract(speed_a * time)"));
  s.inputs.push_back(ports::derived("scroll_b", Type::Vec2, "the second layer's scroll fract(speed_b * time)"));
  s.outputs = {ports::fixed("normal", Type::Vec3, "unit world-space normal"),
               ports::fixed("tangent_normal", Type::Vec3, "the blended unit tangent-space normal, before strength")};
  s.bypass = {{"normal", "normal", std::nullopt}, {"tangent_normal", "", Value::vector({0, 0, 1})}};
  s.options = {
      ports::texture("texture", "builtin:water_normal", "the tangent-space normal map (rgb = n * 0.5 + 0.5)"),
      ports::knob(ports::choice("blend", {"add", "whiteout", "rnm"}, "add",
                               "how the layers combine: the sources' normalize(a + b), whiteout, or reoriented normal mapping"),
                  {"add", "whiteout", "rnm"}),
  };
  s.isSource = true;
  // wg_waves_tangent_to_world: unit, or the up vector when degenerate.
  s.parseOptions = optionParser(parseNormalMapScrollOptions);
  s.facts = [](const std::vector<ValueFact>&, const ParsedOptions&) {
    return std::vector<ValueFact>{ValueFact::unitVector(), ValueFact::unitVector()};
  };
  s.derive = [](DeriveContext& ctx) {
    ctx.set("scroll_a", deriveScroll(ctx, ctx.input("speed_a"), ctx.input("time")));
    ctx.set("scroll_b", deriveScroll(ctx, ctx.input("speed_b"), ctx.input("time")));
  };
  s.emit = [](EmitContext& ctx) {
    auto layer = [&](const char* scale, const char* scroll) {
      // A layer that neither scales nor scrolls reads the texture at uv itself: uv * 1.0 +
      // 0.0 is uv exactly, but glslang and spirv-opt keep it.
      bool still = ctx.inputFact(scale).isConstant(1) && ctx.inputFact(scroll).isConstant(0);
      GlslExpr uv = still ? ctx.input("uv")
                             : EmitContext::call("wg_normal_map_scroll_uv",
                                                 {ctx.input("uv"), ctx.input(scale), ctx.input(scroll)});
      return ctx.temporary(Type::Vec3,
                           EmitContext::call("wg_normal_map_scroll_unpack", {ctx.sampleTexture("texture", uv)}));
    };
    GlslExpr a = layer("scale_a", "scroll_a"), b = layer("scale_b", "scroll_b");
    GlslExpr n = ctx.temporary(
        Type::Vec3, EmitContext::call(ctx.options<NormalMapScrollOptions>().blendFunction, {a, b}));
    GlslExpr ts = EmitContext::call("wg_normal_map_scroll_strength", {n, ctx.input("strength")});
    // ts is a finite unpacked texel, so the flat frame's zero products are exact zeros.
    auto tc = ctx.inputConstant(ctx.inputIndex("tangent")), bc = ctx.inputConstant(ctx.inputIndex("binormal"));
    bool flat = tc && bc && *tc == Value::vector({1, 0, 0}) && *bc == Value::vector({0, 0, 1});
    ctx.output(0, flat ? EmitContext::call("wg_waves_tangent_to_world_flat", {ts, ctx.input("normal")})
                       : EmitContext::call("wg_waves_tangent_to_world",
                                           {ts, ctx.input("tangent"), ctx.input("binormal"), ctx.input("normal")}));
    ctx.output(1, n);
  };
  s.eval = [](EvalContext& ctx) {
    const Value& uv = ctx.input("uv");
    auto layer = [&](const char* scale, const char* scroll) {
      double k = ctx.scalar(scale);
      const Value& v = ctx.input(scroll);
      return unpack(ctx.sampleTexture("texture", uv[0] * k + v[0], uv[1] * k + v[1]));
    };
    D3 a = layer("scale_a", "scroll_a"), b = layer("scale_b", "scroll_b");
    D3 n = normalMapBlend(ctx.options<NormalMapScrollOptions>().blend, a, b);
    double k = ctx.scalar("strength");
    ctx.output(0, waves::value(tangentToWorld({n.x * k, n.y * k, n.z}, ctx)));
    ctx.output(1, waves::value(n));
  };
  // 8-bit texels interpolated in float; fract(speed * t) at t = 1e6 s carries ~1e-3 texture units in float32.
  // GL_LINEAR on 8-bit textures: hardware filter weights have 8 bits (llvmpipe), so each
  // of the two scrolled samples differs from exact bilinear by up to 1/255.
  s.tolerance = 1e-2;
  s.conditionRoundings = 4;
  s.conditionWhy = "grows with the scrolled coordinates (float32 uv and time inputs of 1e4 and more)";
  s.hardCases = {
      {"huge time 1e6 s (as a time input)",
       {{"time", Value::scalar(1e6)}},
       {{"blend", "rnm"}},
       "finite, unit normal",
       -1,
       1,
       "normal"},
      {"time 524288 s",
       {{"time", Value::scalar(524288)}},
       {{"blend", "whiteout"}},
       "finite, unit normal",
       -1,
       1,
       "normal"},
      {"zero frame (normal, tangent, binormal zero)",
       {{"normal", Value::vector({0, 0, 0})},
        {"tangent", Value::vector({0, 0, 0})},
        {"binormal", Value::vector({0, 0, 0})}},
       {},
       "the up vector, not NaN",
       -1,
       1,
       "normal"},
      {"zero strength", {{"strength", Value::scalar(0)}}, {{"blend", "rnm"}}, "the surface normal", -1, 1, "normal"},
  };
  return s;
}

NodeSpec normalFromHeightNode() {
  NodeSpec s;
  s.type = "normal_from_height";
  s.family = "waves";
  s.summary = "Normal of a height texture by central differences, taken to world space.";
  s.formula =
      "e = max(offset, 1/1024); c = fract(uv); g = (h(c + (e,0)) - h(c - (e,0)), h(c + (0,e)) - h(c - (0,e))) / (2 e) "
      "(red channel, bilinear as GL_LINEAR + GL_REPEAT, computed from four texelFetch in float); "
      "n_ts = (-strength g.x, -strength g.y, 1); normal = normalize(T n_ts.x + B n_ts.y + N n_ts.z) (up if "
      "degenerate).";
  s.source = "deferred water article (wave normals from four height-texture samples, Height1 - Height2 and Height3 - Height4)";
  s.cost = "sixteen texelFetch (twenty with the height output), ~60 ALU: filtering in float keeps the gradient exact";
  s.inputs = {
      ports::fromBuiltin("uv", Type::Vec2, Builtin::Uv, "texture coordinate"),
      ports::fixed("offset", Type::Float, Value::scalar(1.0 / 256.0),
                   "sample distance in texture units (one texel of a 256 texture)"),
      ports::fixed("strength", Type::Float, Value::scalar(0.1), "height per texture unit: scales the slope"),
  };
  for (auto& p : framePorts()) s.inputs.push_back(p);
  s.outputs = {ports::fixed("normal", Type::Vec3, "unit world-space normal"),
               ports::fixed("height", Type::Float, "the height sample at uv, in [0, 1]"),
               ports::fixed("gradient", Type::Vec2, "dh/du, dh/dv in texture units")};
  s.options = {ports::texture("texture", "builtin:height", "the height texture (red channel)")};
  s.isSource = true;
  // wg_waves_tangent_to_world: unit, or the up vector when degenerate.
  s.facts = [](const std::vector<ValueFact>&, const ParsedOptions&) {
    return std::vector<ValueFact>{ValueFact::unitVector(), {}, {}};
  };
  s.emit = [](EmitContext& ctx) {
    GlslExpr tex = ctx.texture("texture");
    GlslExpr uv = ctx.temporary(Type::Vec2, ctx.input("uv"));
    GlslExpr g =
        ctx.temporary(Type::Vec2, EmitContext::call("wg_normal_from_height_gradient", {tex, uv, ctx.input("offset")}));
    GlslExpr k = ctx.temporary(Type::Float, ctx.input("strength"));
    ctx.output(
        0, EmitContext::call("wg_waves_tangent_to_world", {"vec3(-" + k + " * " + g + ", 1.0)", ctx.input("tangent"),
                                                           ctx.input("binormal"), ctx.input("normal")}));
    ctx.output(1, EmitContext::call("wg_bilinear_red", {tex, "fract(" + uv + ")"}));
    ctx.output(2, g);
  };
  s.eval = [](EvalContext& ctx) {
    const Value& uv = ctx.input("uv");
    double e = std::max(ctx.scalar("offset"), 1.0 / 1024.0);
    // Around fract(uv), as the GLSL: the texture repeats.
    double cu = uv[0] - std::floor(uv[0]), cv = uv[1] - std::floor(uv[1]);
    auto h = [&](double du, double dv) { return ctx.sampleTexture("texture", cu + du, cv + dv)[0]; };
    double gx = (h(e, 0) - h(-e, 0)) * (0.5 / e), gy = (h(0, e) - h(0, -e)) * (0.5 / e);
    double k = ctx.scalar("strength");
    ctx.output(0, waves::value(tangentToWorld({-k * gx, -k * gy, 1.0}, ctx)));
    ctx.output(1, Value::scalar(h(0, 0)));
    ctx.output(2, Value::vector({gx, gy}));
  };
  // Differences divided by 2e amplify float32 rounding of the coordinates (filtering in
  // float: hardware filtering's 8-bit weights gave gradient errors of 0.4 on llvmpipe).
  s.tolerance = 1e-3;
  s.hardCases = {
      {"zero offset", {{"offset", Value::scalar(0)}}, {}, "finite: the offset is floored at 1/1024", -1, 1, "normal"},
      {"huge coordinates",
       {{"uv", Value::vector({1e5, -1e5})}},
       {},
       "finite, unit normal (the texture repeats)",
       -1,
       1,
       "normal"},
      {"zero frame",
       {{"normal", Value::vector({0, 0, 0})},
        {"tangent", Value::vector({0, 0, 0})},
        {"binormal", Value::vector({0, 0, 0})}},
       {},
       "the up vector, not NaN",
       -1,
       1,
       "normal"},
  };
  return s;
}

NodeSpec dudvDistortionNode() {
  NodeSpec s;
  s.type = "dudv_distortion";
  s.family = "waves";
  s.summary = "The classic WebGL water renderer's du/dv map distortion: a scrolling offset for the refraction and reflection lookups.";
  s.formula =
      "move = fract(time * wave_speed); offset = (dudv(uv * tiling + (move, 0)).rg * 2 - 1) * strength; "
      "uv_out = target_uv + offset.";
  s.source = "classic WebGL water renderer (dudvOffset = time / 1000 * waveSpeed with time in ms, (dudv * 2 - 1) * 0.03, tiling 4)";
  s.cost = "one texture fetch, ~6 ALU";
  s.inputs = {
      ports::fromBuiltin("uv", Type::Vec2, Builtin::Uv, "the surface's texture coordinate"),
      ports::fromBuiltin("time", Type::Float, Builtin::Time, "seconds"),
      ports::fromBuiltin("target_uv", Type::Vec2, Builtin::ScreenUv,
                         "the coordinate to distort (the screen position of the refraction/reflection lookup)"),
      ports::fixed("tiling", Type::Float, Value::scalar(4.0), "repeats of the du/dv map per uv unit (source: 4)"),
      ports::fixed("wave_speed", Type::Float, Value::scalar(0.03), "scroll speed, texture units per second"),
      ports::fixed("strength", Type::Float, Value::scalar(0.03), "distortion strength (source: 0.03)"),
  };
  s.outputs = {ports::fixed("offset", Type::Vec2, "the distortion, within [-strength, strength]"),
               ports::fixed("uv", Type::Vec2, "target_uv + offset"),
               ports::fixed("move", Type::Float, "the scroll fract(time * wave_speed), in [0, 1)")};
  s.inputs.push_back(ports::derived("scroll", Type::Float, "the scroll fract(time * wave_speed)"));
  s.options = {ports::texture("texture", "builtin:dudv", "the du/dv map (rg)")};
  // The scroll is the same for every pixel of a draw: ops of its own.
  s.derive = [](DeriveContext& ctx) { ctx.set("scroll", deriveScroll(ctx, ctx.input("wave_speed"), ctx.input("time"))); };
  s.stages = kFragmentStage;  // target_uv defaults to the screen position
  s.isSource = true;
  s.emit = [](EmitContext& ctx) {
    GlslExpr tex = ctx.texture("texture");
    GlslExpr move = ctx.input("scroll");
    GlslExpr d = ctx.temporary(
        Type::Vec2, EmitContext::call("wg_dudv_distortion_offset",
                                      {tex, ctx.input("uv"), ctx.input("tiling"), move, ctx.input("strength")}));
    ctx.output(0, d);
    ctx.output(1, "(" + ctx.input("target_uv") + " + " + d + ")");
    ctx.output(2, move);
  };
  s.eval = [](EvalContext& ctx) {
    double move = ctx.scalar("scroll");
    const Value& uv = ctx.input("uv");
    double tiling = ctx.scalar("tiling"), k = ctx.scalar("strength");
    Value t = ctx.sampleTexture("texture", uv[0] * tiling + move, uv[1] * tiling);
    double dx = (t[0] * 2.0 - 1.0) * k, dy = (t[1] * 2.0 - 1.0) * k;
    const Value& target = ctx.input("target_uv");
    ctx.output(0, Value::vector({dx, dy}));
    ctx.output(1, Value::vector({target[0] + dx, target[1] + dy}));
    ctx.output(2, Value::scalar(move));
  };
  // fract(time * speed) in float32 at t = 524288 s: ~1e-3 texture units of scroll. Past
  // that the product's rounding grows with it (at t = 1e7 s, speed 0.03: the scroll moves in
  // steps of 1/32): the conditioning of time * speed, one rounding.
  s.tolerance = 1e-3;
  s.conditionRoundings = 1;
  s.conditionWhy = "grows with time * wave_speed: the scroll fract(time * wave_speed) is formed in float32 in the shader";
  s.hardCases = {
      {"time 524288 s", {{"time", Value::scalar(524288)}}, {}, "finite, |offset| <= 0.03", -0.03, 0.03, "offset"},
      {"time 13107 s", {{"time", Value::scalar(13107)}}, {}, "finite, |offset| <= 0.03", -0.03, 0.03, "offset"},
      {"huge uv", {{"uv", Value::vector({1e5, 1e5})}}, {}, "finite (the texture repeats)", -0.03, 0.03, "offset"},
  };
  return s;
}

}  // namespace wg::nodes
