// trochoid_wave: the deferred water article's 3D wave. The water is drawn as a flat surface; per pixel, a
// bisection along the view ray finds where the ray meets the displaced surface
// h(x, z) = A (sin(phi - 0.5 cos phi) + detail (2 tex(uv) - 1)), a trochoid-like profile
// (sharp crests, flat troughs) plus a height-texture detail.
#include <algorithm>
#include <cmath>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"
#include "nodes/waves_common.h"

namespace wg::nodes {
namespace {

using waves::D3;

struct TrochoidSetup {
  double amplitude, waveX, waveZ, timePhase, detail, texScale;
  const EvalContext* ctx;

  double phase(double x, double z) const { return glsl::mod(waveX * x + waveZ * z + timePhase, waves::kTwoPi); }
  double tex(double u, double v) const { return ctx->sampleTexture("texture", u, v)[0]; }
  double height(double x, double z) const {
    double phi = phase(x, z);
    double h = tex(texScale * x + 0.5, 0.5 - texScale * z);
    return amplitude * (std::sin(phi - 0.5 * std::cos(phi)) + detail * (2.0 * h - 1.0));
  }
};

struct TrochoidWaveOptions {
  int steps;
  double omega;  // rad/s of the phase
};
TrochoidWaveOptions parseTrochoidWaveOptions(const OptionReader& o) { return {o.integer("steps"), o.number("omega")}; }

}  // namespace

NodeSpec trochoidWaveNode() {
  NodeSpec s;
  s.type = "trochoid_wave";
  s.family = "waves";
  s.summary = "The deferred water article's trochoid-like wave found along the view ray by bisection: hit point, height and normal.";
  s.formula =
      "h(x, z) = A (sin(phi - 0.5 cos phi) + detail (2 T(s x + 0.5, 0.5 - s z).r - 1)), "
      "phi = mod(K.(x, z) + mod(omega t, 2 pi), 2 pi). Ray: origin O, direction R = -normalize(view); P0 = O + t0 R "
      "with t0 = clamp((surface_height - O.y) / R.y, 0, max_distance) (|R.y| floored at 1e-6). "
      "M = A (1 + |detail|); step = +-M / max(|R.y|, 0.1) (+ when O is above the surface); P = P0; repeat `steps` "
      "times: step /= 2; P -= step R if P.y - surface_height < h(P.xz), else P += step R. The deferred water article searches only the "
      "10 M before P0 and misses troughs below the plane; the search here is centred on P0. Rays flatter than "
      "|R.y| = 0.1 search 10 M each side of P0 (the deferred water article's range) and can stop short of a deep trough. "
      "Outputs P, h(P.xz) and normalize(-dh/dx, 1, -dh/dz) with dh = A (cos(phi - 0.5 cos phi)(1 + 0.5 sin phi) K "
      "+ detail * 2 * dT) where dT is the texture's central difference `normal_offset` apart.";
  s.source =
      "deferred water article (listing 6: 10-step bisection, sin(phase - 0.5 cos(phase)), height-texture detail with texture "
      "coordinate (s x + 0.5, 0.5 - s z), search range up to 10 x the maximum wave amplitude)";
  s.cost =
      "per step: one texture fetch, sin, cos, ~15 ALU (steps = 10 by default: 10 fetches); the height at the hit "
      "adds one fetch and the normal four. Position error after n steps: A (1 + |detail|) / max(|R.y|, 0.1) / 2^n "
      "along the ray.";
  s.inputs = {
      ports::fromBuiltin("origin", Type::Vec3, Builtin::CameraPosition, "where the ray starts (the camera)"),
      ports::fromBuiltin("view", Type::Vec3, Builtin::ViewDirection,
                         "unit vector from the surface to the viewer; the ray runs along -view"),
      ports::fixed("surface_height", Type::Float, Value::scalar(0.0), "height y of the flat water surface"),
      ports::fixed("amplitude", Type::Float, Value::scalar(0.5), "wave amplitude A in metres (source: NegWindVector.y)"),
      ports::fixed("wave_vector", Type::Vec2, Value::vector({0.3, 0.2}),
                   "K: wave number times direction over (x, z), rad/m (source: NegWindVector.xz)"),
      ports::fixed("detail", Type::Float, Value::scalar(0.3),
                   "height-texture detail relative to A (source: WaveFrontValues.x)"),
      ports::fixed("texture_scale", Type::Float, Value::scalar(0.01),
                   "texture repeats per metre s (source: WaveValues.x)"),
      ports::fixed("normal_offset", Type::Float, Value::scalar(1.0 / 256.0),
                   "texture-space distance of the detail's central differences (floored at 1e-6)"),
      ports::fixed("max_distance", Type::Float, Value::scalar(1e4),
                   "farthest ray distance to the flat surface (grazing rays are clamped here)"),
  };
  s.outputs = {ports::fixed("position", Type::Vec3, "the point on the wave surface where the ray meets it"),
               ports::fixed("height", Type::Float, "the wave height h above surface_height at the hit point"),
               ports::fixed("normal", Type::Vec3, "unit normal of the wave surface at the hit point")};
  s.options = {
      ports::knob(ports::integer("steps", 10, 1, 32, "bisection steps: each halves the position error"), {2, 5, 10, 20, 32}),
      ports::number("omega", 1.0, 0.0, 100.0, "angular speed of the phase in rad/s (the deferred water article adds the time itself: 1)"),
      ports::texture("texture", "builtin:height", "the height texture (red channel) of the detail"),
  };
  s.isSource = true;
  // wg_trochoid_wave_normal: wg_safe_normalize_vec3 of (.., 1.0, ..).
  s.facts = [](const std::vector<ValueFact>&, const ParsedOptions&) { return std::vector<ValueFact>{{}, {}, ValueFact::unitVector()}; };
  s.parseOptions = optionParser(parseTrochoidWaveOptions);
  s.emit = [](EmitContext& ctx) {
    GlslExpr tex = ctx.texture("texture");
    GlslExpr phase = ctx.timePhase(ctx.options<TrochoidWaveOptions>().omega);
    GlslExpr steps = std::to_string(ctx.options<TrochoidWaveOptions>().steps);
    GlslExpr dir = ctx.temporary(Type::Vec3, "-" + EmitContext::call("wg_safe_normalize_vec3", {ctx.input("view")}));
    GlslExpr amp = ctx.temporary(Type::Float, ctx.input("amplitude"));
    GlslExpr k = ctx.temporary(Type::Vec2, ctx.input("wave_vector"));
    GlslExpr detail = ctx.temporary(Type::Float, ctx.input("detail"));
    GlslExpr scale = ctx.temporary(Type::Float, ctx.input("texture_scale"));
    GlslExpr hit = ctx.temporary(
        Type::Vec3,
        EmitContext::call("wg_trochoid_wave_march", {ctx.input("origin"), dir, ctx.input("surface_height"), amp, k,
                                                     phase, detail, scale, ctx.input("max_distance"), steps, tex}));
    ctx.output(0, hit);
    ctx.output(1, EmitContext::call("wg_trochoid_wave_height", {hit + ".xz", amp, k, phase, detail, scale, tex}));
    ctx.output(2, EmitContext::call("wg_trochoid_wave_normal",
                                    {hit + ".xz", amp, k, phase, detail, scale, ctx.input("normal_offset"), tex}));
  };
  s.eval = [](EvalContext& ctx) {
    const Value& k = ctx.input("wave_vector");
    TrochoidSetup w{ctx.scalar("amplitude"),
                    k[0],
                    k[1],
                    waves::timePhase(ctx, ctx.options<TrochoidWaveOptions>().omega),
                    ctx.scalar("detail"),
                    ctx.scalar("texture_scale"),
                    &ctx};
    D3 origin = waves::d3(ctx.input("origin"));
    D3 dir = waves::safeNormalize(waves::d3(ctx.input("view"))) * -1.0;
    double surfaceY = ctx.scalar("surface_height");
    double dy = std::abs(dir.y) < 1e-6 ? (dir.y < 0 ? -1e-6 : 1e-6) : dir.y;
    double t0 = glsl::clamp((surfaceY - origin.y) / dy, 0.0, ctx.scalar("max_distance"));
    D3 p = origin + dir * t0;
    double maxAmplitude = std::abs(w.amplitude) * (1.0 + std::abs(w.detail));
    double step = (origin.y > surfaceY ? 1.0 : -1.0) * maxAmplitude / std::max(std::abs(dir.y), 0.1);
    int steps = ctx.options<TrochoidWaveOptions>().steps;
    for (int i = 0; i < steps; ++i) {
      double h = w.height(p.x, p.z);
      step *= 0.5;
      p = p + dir * ((p.y - surfaceY) < h ? -step : step);
    }
    ctx.output(0, waves::value(p));
    ctx.output(1, Value::scalar(w.height(p.x, p.z)));
    double phi = w.phase(p.x, p.z);
    double dphi = std::cos(phi - 0.5 * std::cos(phi)) * (1.0 + 0.5 * std::sin(phi));
    double e = ctx.scalar("normal_offset");
    double u = w.texScale * p.x + 0.5, v = 0.5 - w.texScale * p.z;
    double du = w.tex(u + e, v) - w.tex(u - e, v);
    double dv = w.tex(u, v + e) - w.tex(u, v - e);
    double inv2e = 0.5 / std::max(e, 1e-6);
    double dhdx = w.amplitude * (dphi * w.waveX + w.detail * 2.0 * du * inv2e * w.texScale);
    double dhdz = w.amplitude * (dphi * w.waveZ - w.detail * 2.0 * dv * inv2e * w.texScale);
    ctx.output(2, waves::value(waves::safeNormalize({-dhdx, 1.0, -dhdz})));
  };
  // The bisection's last step is A (1 + detail) / max(|R.y|, 0.1) / 2^steps (<= 6.3 mm by default): a float32
  // decision that differs from the double one near the surface moves the hit by up to about twice that.
  s.tolerance = 1e-2;
  s.hardCases = {
      {"grazing ray (view horizontal)",
       {{"view", Value::vector({1, 0, 0})}, {"origin", Value::vector({0, 10, 0})}},
       {},
       "finite: the ray distance is clamped to max_distance",
       -1,
       1,
       "normal"},
      {"zero view vector",
       {{"view", Value::vector({0, 0, 0})}},
       {},
       "finite: safe normalize gives a zero ray",
       -1,
       1,
       "normal"},
      {"camera below the surface looking up",
       {{"origin", Value::vector({0, -5, 0})}, {"view", Value::vector({0, -1, 0})}},
       {},
       "finite, the search runs beyond the flat surface",
       -1,
       1,
       "normal"},
      {"huge coordinates 1e5 m",
       {{"origin", Value::vector({1e5, 10, -1e5})}, {"view", Value::vector({0.6, 0.8, 0})}},
       {},
       "finite: the phase is wrapped before sin",
       -1,
       1,
       "normal"},
      {"zero amplitude", {{"amplitude", Value::scalar(0)}}, {}, "the flat surface, normal up", -1, 1, "normal"},
  };
  return s;
}

}  // namespace wg::nodes
