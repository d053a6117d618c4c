// analytic_normals.cpp — sine_normals: the advanced shaders tutorial's procedural wave normals from layered sines, and the top-down water plan's
// high-frequency ripple normals (ripple_normals). Both tilt a normal by analytic sine noise
// with constant angular speeds, so every time term is an exact CPU-side phase uniform.
#include <cmath>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"
#include "nodes/waves_common.h"

namespace wg::nodes {
namespace {

using waves::D3;

double wrap(double x) { return glsl::mod(x, waves::kTwoPi); }

// The advanced shaders tutorial's three layers, (dn.x, dn.z) each, as the GLSL computes them.
void sineLayer(int layer, double x, double z, const EvalContext& ctx, double out[2]) {
  auto ph = [&](double w) { return waves::timePhase(ctx, w); };
  if (layer == 0) {
    double a = wrap(0.5 * x) + ph(0.8);
    double w = std::sin(a) * std::cos(wrap(0.3 * z) + ph(0.6));
    out[0] = w * 0.3;
    out[1] = std::cos(a) * 0.2;
  } else if (layer == 1) {
    double w = std::sin(wrap(2.0 * x + 1.5 * z) + ph(2.0));
    out[0] = w * 0.15;
    out[1] = std::cos(wrap(1.5 * x - 2.0 * z) + ph(1.8)) * 0.1;
  } else {
    double w = std::sin(wrap(8.0 * x) - ph(3.0)) * std::sin(wrap(6.0 * z) + ph(2.5));
    out[0] = w * 0.05;
    out[1] = w * 0.05;
  }
}

// The top-down water plan's ripple layers: frequencies (fa, fb), time phases (signed omegas) and weight.
struct RippleLayer {
  double fa[2], fb[2];
  double omegaA, omegaB;  // signed: the phase added is sign * mod(|omega| t, 2 pi)
  double weight;
};
constexpr RippleLayer kRipples[3] = {
    {{23, 17}, {19, -23}, 2.3, 1.9, 0.5},
    {{47, 31}, {37, -43}, -3.1, 2.7, 0.3},
    {{89, -67}, {73, 61}, 4.1, -3.7, 0.2},
};

}  // namespace

namespace {

struct OctaveOptions {
  int octaves;  // how many of the source's layers
};
OctaveOptions parseOctaveOptions(const OptionReader& o) { return {o.integer("octaves")}; }

}  // namespace

NodeSpec sineNormalsNode() {
  NodeSpec s;
  s.type = "sine_normals";
  s.family = "waves";
  s.summary = "The advanced shaders tutorial's animated wave normals from layered sines (no texture).";
  s.formula =
      "p = position.xz * scale. Layer 1: w1 = sin(0.5 p.x + 0.8 t) cos(0.3 p.y + 0.6 t), dn += (0.3 w1, 0.2 cos(0.5 "
      "p.x "
      "+ 0.8 t)); layer 2: dn += (0.15 sin(2 p.x + 1.5 p.y + 2 t), 0.1 cos(1.5 p.x - 2 p.y + 1.8 t)); layer 3: "
      "w3 = sin(8 p.x - 3 t) sin(6 p.y + 2.5 t), dn += (0.05 w3, 0.05 w3). normal = normalize(strength dn.x, 1, "
      "strength dn.y) for a y-up plane. Spatial parts are wrapped mod 2 pi; time parts are mod(omega t, 2 pi) "
      "uniforms.";
  s.source = "advanced shaders tutorial (computeWaveNormal, approach 1: three layers of sines)";
  s.cost = "octaves = 1: 3 sin/cos, ~12 ALU; 2: +2 sin/cos; 3: +2 sin; each layer adds two phase uniforms";
  s.inputs = {
      ports::fromBuiltin("position", Type::Vec3, Builtin::WorldPosition, "the surface point; x and z are used"),
      ports::fixed("scale", Type::Float, Value::scalar(1.0), "multiplies the position (smaller = larger waves)"),
      ports::fixed("strength", Type::Float, Value::scalar(1.0), "multiplies the tilt (0 = flat)"),
  };
  s.outputs = {ports::fixed("normal", Type::Vec3, "unit normal of a y-up plane tilted by the sines"),
               ports::fixed("slope", Type::Vec2, "the tilt (dn.x, dn.z) before strength and normalisation")};
  s.options = {ports::knob(ports::integer("octaves", 3, 1, 3, "how many of the source's three layers"), {1, 2, 3})};
  s.parseOptions = optionParser(parseOctaveOptions);
  s.isSource = true;
  // wg_safe_normalize_vec3 of (.., 1.0, ..): unit (zero only if the slope overflows).
  s.facts = [](const std::vector<ValueFact>&, const ParsedOptions&) { return std::vector<ValueFact>{ValueFact::unitVector(), {}}; };
  s.emit = [](EmitContext& ctx) {
    int octaves = ctx.options<OctaveOptions>().octaves;
    GlslExpr p = ctx.temporary(Type::Vec2, ctx.input("position") + ".xz * " + ctx.input("scale"));
    static const double kOmega[3][2] = {{0.8, 0.6}, {2.0, 1.8}, {3.0, 2.5}};
    GlslExpr sum;
    for (int i = 0; i < octaves; ++i) {
      GlslExpr layer = EmitContext::call("wg_sine_normals_layer" + std::to_string(i + 1),
                                            {p, ctx.timePhase(kOmega[i][0]), ctx.timePhase(kOmega[i][1])});
      sum += (sum.empty() ? "" : " + ") + layer;
    }
    GlslExpr slope = ctx.temporary(Type::Vec2, sum);
    GlslExpr k = ctx.temporary(Type::Float, ctx.input("strength"));
    ctx.output(0, EmitContext::call("wg_safe_normalize_vec3",
                                    {"vec3(" + k + " * " + slope + ".x, 1.0, " + k + " * " + slope + ".y)"}));
    ctx.output(1, slope);
  };
  s.eval = [](EvalContext& ctx) {
    int octaves = ctx.options<OctaveOptions>().octaves;
    const Value& pos = ctx.input("position");
    double scale = ctx.scalar("scale"), k = ctx.scalar("strength");
    double x = pos[0] * scale, z = pos[2] * scale;
    double dn[2] = {0, 0};
    for (int i = 0; i < octaves; ++i) {
      double l[2];
      sineLayer(i, x, z, ctx, l);
      dn[0] += l[0];
      dn[1] += l[1];
    }
    ctx.output(0, waves::value(waves::safeNormalize({k * dn[0], 1.0, k * dn[1]})));
    ctx.output(1, Value::vector({dn[0], dn[1]}));
  };
  s.tolerance = 1e-4;
  s.conditionRoundings = 4;
  s.conditionWhy = "grows with the phases k x of positions (float32 spacing 7.8 mm at 1e5 m)";
  s.hardCases = {
      {"huge coordinates 1e5 m",
       {{"position", Value::vector({1e5, 0, -1e5})}},
       {},
       "finite, unit normal",
       -1,
       1,
       "normal"},
      {"large strength",
       {{"strength", Value::scalar(1e3)}},
       {},
       "finite: the normal lies nearly flat",
       -1,
       1,
       "normal"},
      {"zero scale", {{"scale", Value::scalar(0)}}, {}, "finite, the normal of the origin", -1, 1, "normal"},
  };
  return s;
}

NodeSpec rippleNormalsNode() {
  NodeSpec s;
  s.type = "ripple_normals";
  s.family = "waves";
  s.summary = "The top-down water plan's high-frequency ripple normals: analytic sine noise added to a normal.";
  s.formula =
      "uv = position.xz * scale * 0.08; r = 0.5 (sin(23 u + 17 v + 2.3 t), sin(19 u - 23 v + 1.9 t)) + 0.3 "
      "(sin(47 u + 31 v - 3.1 t), sin(37 u - 43 v + 2.7 t)) + 0.2 (sin(89 u - 67 v + 4.1 t), sin(73 u + 61 v - 3.7 "
      "t)); "
      "normal = normalize(N + strength (r.x, 0, r.y)). The top-down water plan is top-down (z up) and perturbs N.xy; in this y-up "
      "world r.x goes to x and r.y to z.";
  s.source = "top-down water plan (rippleNoise, u_rippleStrength 0.15, u_rippleScale 1.0, the 0.08 world-to-noise factor)";
  s.cost = "per octave: 2 sin, ~10 ALU and two phase uniforms (octaves = 3: 6 sin)";
  s.inputs = {
      ports::fromBuiltin("position", Type::Vec3, Builtin::WorldPosition, "the surface point; x and z are used"),
      ports::fromBuiltin("normal", Type::Vec3, Builtin::Normal, "the normal to perturb"),
      ports::fixed("strength", Type::Float, Value::scalar(0.15), "perturbation strength (source: u_rippleStrength)"),
      ports::fixed("scale", Type::Float, Value::scalar(1.0), "world-space scale (source: u_rippleScale)"),
  };
  s.outputs = {ports::fixed("normal", Type::Vec3, "the perturbed unit normal (up when it degenerates)"),
               ports::fixed("ripple", Type::Vec2, "the ripple noise r, in [-1, 1]")};
  s.options = {ports::knob(ports::integer("octaves", 3, 1, 3, "how many of the source's three layers"), {1, 2, 3})};
  s.parseOptions = optionParser(parseOctaveOptions);
  s.isSource = true;
  // wg_waves_unit_or_vec3: unit, or the up vector when degenerate.
  s.facts = [](const std::vector<ValueFact>&, const ParsedOptions&) { return std::vector<ValueFact>{ValueFact::unitVector(), {}}; };
  s.emit = [](EmitContext& ctx) {
    int octaves = ctx.options<OctaveOptions>().octaves;
    GlslExpr uv = ctx.temporary(Type::Vec2, ctx.input("position") + ".xz * (" + ctx.input("scale") + " * 0.08)");
    GlslExpr sum;
    for (int i = 0; i < octaves; ++i) {
      const RippleLayer& l = kRipples[i];
      auto phase = [&](double w) { return (w < 0 ? "-" : "") + ctx.timePhase(std::abs(w)); };
      // One phase per statement: the operands of + are evaluated in an unspecified order
      // (GCC and Clang differ), and each call names the next phase uniform.
      GlslExpr phaseA = phase(l.omegaA);
      GlslExpr phaseB = phase(l.omegaB);
      GlslExpr layer = EmitContext::call("wg_ripple_normals_layer",
                                            {uv, ctx.literal(Value::vector({l.fa[0], l.fa[1], l.fb[0], l.fb[1]})),
                                             "vec2(" + phaseA + ", " + phaseB + ")"});
      sum += (sum.empty() ? "" : " + ") + layer + " * " + ctx.literal(l.weight);
    }
    GlslExpr r = ctx.temporary(Type::Vec2, sum);
    ctx.output(0, EmitContext::call("wg_waves_unit_or_vec3", {ctx.input("normal") + " + " + ctx.input("strength") +
                                                                  " * vec3(" + r + ".x, 0.0, " + r + ".y)",
                                                              "vec3(0.0, 1.0, 0.0)"}));
    ctx.output(1, r);
  };
  s.eval = [](EvalContext& ctx) {
    int octaves = ctx.options<OctaveOptions>().octaves;
    const Value& pos = ctx.input("position");
    double f = ctx.scalar("scale") * 0.08;
    double u = pos[0] * f, v = pos[2] * f;
    double r[2] = {0, 0};
    for (int i = 0; i < octaves; ++i) {
      const RippleLayer& l = kRipples[i];
      auto phase = [&](double w) { return (w < 0 ? -1.0 : 1.0) * waves::timePhase(ctx, std::abs(w)); };
      r[0] += std::sin(wrap(l.fa[0] * u + l.fa[1] * v) + phase(l.omegaA)) * l.weight;
      r[1] += std::sin(wrap(l.fb[0] * u + l.fb[1] * v) + phase(l.omegaB)) * l.weight;
    }
    double k = ctx.scalar("strength");
    D3 n = waves::d3(ctx.input("normal")) + D3{k * r[0], 0.0, k * r[1]};
    ctx.output(0, waves::value(waves::unitOr(n, {0, 1, 0})));
    ctx.output(1, Value::vector({r[0], r[1]}));
  };
  s.tolerance = 1e-4;
  s.conditionRoundings = 4;
  s.conditionWhy = "grows with the phases k x of positions (float32 spacing 7.8 mm at 1e5 m)";
  s.hardCases = {
      {"huge coordinates 1e5 m",
       {{"position", Value::vector({1e5, 0, 1e5})}},
       {},
       "finite, unit normal",
       -1,
       1,
       "normal"},
      {"zero normal and zero strength",
       {{"normal", Value::vector({0, 0, 0})}, {"strength", Value::scalar(0)}},
       {},
       "the up vector, not NaN",
       -1,
       1,
       "normal"},
      {"large strength",
       {{"strength", Value::scalar(1e3)}},
       {},
       "finite, a nearly horizontal unit normal",
       -1,
       1,
       "normal"},
  };
  return s;
}

}  // namespace wg::nodes
