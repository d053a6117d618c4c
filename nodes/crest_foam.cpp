// crest_foam: the top-down water plan's whitecaps, foam where the wave is high or steep, broken into
// patches by two layers of drifting value noise (threshold, intensity, coverage, sharpness).
#include <algorithm>
#include <cmath>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/foam_caustics_reference.h"
#include "nodes/node_library.h"
#include "nodes/noise_reference.h"
#include "nodes/port_builders.h"

namespace wg::nodes {
namespace {

// The noise lattice repeats every 256 cells, so a drift wrapped to 256 is seamless.
constexpr double kPeriod = 256.0;
constexpr std::uint32_t kMask = 255u;
// The top-down water plan: noise(xz * 0.12 + 0.3 t) + 0.5 noise(xz * 0.25 - 0.2 t).
constexpr double kDrift1 = 0.3, kDrift2 = 0.2;

// The angular speed whose phase, scaled by period / 2 pi, is mod(rate t, period).
double crestDriftOmega(double rate) { return glsl::kTau * rate / kPeriod; }

}  // namespace

// The top-down water plan's calculateFoam with y up, as nodes/glsl/crest_foam.glsl.
double crestFoamReference(double height, const Value& normal, double x, double z, double drift1, double drift2,
                          double threshold, double intensity, double coverage, double sharpness) {
  double heightFoam = glsl::safeSmoothstep(threshold, threshold + 0.15, height);
  Value n = glsl::safeNormalize(normal);
  double slopeFoam = glsl::safeSmoothstep(0.3, 0.7, std::sqrt(n[0] * n[0] + n[2] * n[2]));
  double base = std::max(heightFoam, slopeFoam * 0.4);
  double nz = (noise::valueNoiseTiled2(x * 0.12 + drift1, z * 0.12 + drift1, kMask) +
               0.5 * noise::valueNoiseTiled2(x * 0.25 - drift2, z * 0.25 - drift2, kMask)) /
              1.5;
  double t = 1.0 - coverage;
  double mask = glsl::safeSmoothstep(t - 0.1, t + 0.1, nz);
  return glsl::safePow(glsl::saturate(base * mask * intensity), 1.0 / std::max(sharpness, 1e-3));
}

namespace {

struct CrestFoamOptions {
  double noiseSpeed;
};
CrestFoamOptions parseCrestFoamOptions(const OptionReader& o) { return {o.number("noise_speed")}; }

}  // namespace

NodeSpec crestFoamNode() {
  NodeSpec s;
  s.type = "crest_foam";
  s.family = "foam";
  s.summary = "Whitecaps at wave crests from height and slope, broken into drifting patches by value noise (the top-down water plan).";
  s.formula =
      "h = smoothstep(threshold, threshold + 0.15, height); slope = |normalize(N).xz|; base = max(h, 0.4 smoothstep(0.3, "
      "0.7, slope)); n = (vn(0.12 xz + 0.3 s t) + 0.5 vn(0.25 xz - 0.2 s t)) / 1.5 (s = noise_speed, value noise on a "
      "256-cell tiling lattice, drifts wrapped to 256); mask = smoothstep(0.9 - coverage, 1.1 - coverage, n); "
      "foam = clamp(base mask intensity, 0, 1)^(1 / max(sharpness, 1e-3)).";
  s.source = "top-down water plan (calculateFoam: threshold 0.65, intensity 0.7, coverage 0.4, sharpness 3)";
  s.cost = "8 hashes (two 2D value noises) + ~45 ALU + exp2/log2; two time-phase uniforms";
  s.inputs = {
      ports::fixed("height", Type::Float, "wave height at the point (the top-down water plan's raw height, ~0..1), e.g. from gerstner_waves"),
      ports::fromBuiltin("normal", Type::Vec3, Builtin::Normal, "surface normal, y up (default: the surface normal)"),
      ports::fromBuiltin("position", Type::Vec3, Builtin::WorldPosition,
                         "world point; x and z place the noise (default: the surface position)"),
      ports::fixed("threshold", Type::Float, Value::scalar(0.65), "height where crest foam starts (the top-down water plan: 0.65)"),
      ports::fixed("intensity", Type::Float, Value::scalar(0.7), "overall foam brightness (the top-down water plan: 0.7)"),
      ports::fixed("coverage", Type::Float, Value::scalar(0.4), "how much area gets foam patches, 0..1 (the top-down water plan: 0.4)"),
      ports::fixed("sharpness", Type::Float, Value::scalar(3.0), "edge sharpness: foam^(1/sharpness) (the top-down water plan: 3)"),
  };
  s.outputs = {ports::fixed("foam", Type::Float, "foam amount in [0, 1]")};
  s.bypass = {{"foam", "", Value::scalar(0)}};
  s.options = {ports::number("noise_speed", 1.0, -100.0, 100.0,
                             "multiplies the top-down water plan's noise drift rates 0.3 and 0.2 per second (compile-time: the drift "
                             "is a double-precision time phase, seamless at t = 1e6 s)")};
  s.isSource = true;  // reads time phases
  s.parseOptions = optionParser(parseCrestFoamOptions);
  s.emit = [](EmitContext& ctx) {
    double ns = ctx.options<CrestFoamOptions>().noiseSpeed;
    GlslExpr drift = "vec2(0.0)";
    if (ns != 0.0) {
      GlslExpr p1 = ctx.timePhase(crestDriftOmega(kDrift1 * ns));  // one call per statement: a stable order
      GlslExpr p2 = ctx.timePhase(crestDriftOmega(kDrift2 * ns));
      drift = "vec2(" + p1 + ", " + p2 + ") * " + ctx.literal(kPeriod / glsl::kTau);
    }
    drift = ctx.temporary(Type::Vec2, drift);
    GlslExpr height = ctx.input("height");
    GlslExpr normal = ctx.input("normal");
    GlslExpr position = ctx.input("position");
    ctx.output(0, EmitContext::call("wg_crest_foam", {height, normal, position + ".xz",
                                                      drift, ctx.input("threshold"), ctx.input("intensity"),
                                                      ctx.input("coverage"), ctx.input("sharpness")}));
  };
  s.eval = [](EvalContext& ctx) {
    double ns = ctx.options<CrestFoamOptions>().noiseSpeed;
    double t = ctx.environment().time[0];
    double d1 = 0, d2 = 0;
    if (ns != 0.0) {
      d1 = glsl::mod(crestDriftOmega(kDrift1 * ns) * t, glsl::kTau) * (kPeriod / glsl::kTau);
      d2 = glsl::mod(crestDriftOmega(kDrift2 * ns) * t, glsl::kTau) * (kPeriod / glsl::kTau);
    }
    const Value& pos = ctx.input("position");
    ctx.output(0, Value::scalar(crestFoamReference(ctx.scalar("height"), ctx.input("normal"), pos[0], pos[2], d1, d2,
                                                   ctx.scalar("threshold"), ctx.scalar("intensity"),
                                                   ctx.scalar("coverage"), ctx.scalar("sharpness"))));
  };
  // The 1/sharpness power steepens small values (slope up to ~1/(3 x^(2/3))); away from 0 the
  // float32 result agrees to ~1e-4.
  s.tolerance = 1e-3;
  s.hardCases = {
      {"pow base 0 (flat, low)", {{"height", Value::scalar(0)}, {"normal", Value::vector({0, 1, 0})}}, {}, "0, not NaN", 0, 0},
      {"zero normal", {{"height", Value::scalar(1)}, {"normal", Value::vector({0, 0, 0})}}, {}, "in [0, 1]", 0, 1},
      {"zero and negative sharpness", {{"height", Value::scalar(1)}, {"sharpness", Value::scalar(-2)}, {"coverage", Value::scalar(1)}},
       {}, "sharpness floored: in [0, 1]", 0, 1},
      {"huge coordinates 1e5 m", {{"height", Value::scalar(0.9)}, {"position", Value::vector({1e5, 0, -1e5})}}, {}, "in [0, 1]", 0, 1},
      {"huge intensity", {{"height", Value::scalar(0.9)}, {"intensity", Value::scalar(1e30)}, {"coverage", Value::scalar(1)}},
       {}, "clamped: in [0, 1]", 0, 1},
  };
  return s;
}

}  // namespace wg::nodes
