// color_variation: the top-down water plan's colour variation of the water body (sun-facing slopes warmer,
// a slowly drifting value-noise hue shift, darker troughs). The noise is an integer-hash
// value noise of its own (nodes/glsl/color_variation.glsl), periodic over 256 noise units
// so that its time drift can be wrapped exactly.
#include <cmath>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"
#include "nodes/shading_reference.h"

namespace wg::nodes {
namespace {

constexpr double kNoisePeriod = 256.0;  // the noise lattice's period (color_variation.glsl)

// The drift as a time phase: offset = drift * t mod 256 = phase * 256 / (2 pi) with
// phase = mod(omega t, 2 pi), omega = 2 pi drift / 256.
double variationDriftOmega(double drift) { return glsl::kTau * drift / kNoisePeriod; }

}  // namespace

namespace {

struct ColorVariationOptions {
  double noiseScale, drift;
};
ColorVariationOptions parseColorVariationOptions(const OptionReader& o) {
  return {o.number("noise_scale"), o.number("drift")};
}

}  // namespace

NodeSpec colorVariationNode() {
  NodeSpec s;
  s.type = "color_variation";
  s.family = "depth and colour";
  s.summary = "The top-down water plan's colour variation: sun-facing slopes warmer, a drifting noise hue shift, darker troughs.";
  s.formula =
      "facing = dot(N.xz, S.xz) (N, S normalised; the source's top-down x/y plane is our x/z); slope = mix((-0.03, "
      "-0.01, 0.03), (0.03, 0.05, -0.02), clamp(facing * 0.5 + 0.5, 0, 1)); noise = value_noise(position.xz * "
      "noise_scale + drift * t) with an integer (PCG) lattice hash, period 256 noise units; hue = mix((-0.02, "
      "0.02, 0.04), (0.02, 0.04, -0.02), noise); darken = (1 - clamp(height, 0, 1)) * trough; color = (base + "
      "slope * slope_strength + hue * noise_strength) * (1 - darken).";
  s.source = "top-down water plan (section 5: slopeShift * 0.2, valueNoise(worldPos * 0.02 + time * 0.05), u_colorNoiseStrength = "
             "0.1, troughDarken = (1 - rawHeight) * 0.15)";
  s.cost = "value noise: 4 PCG hashes (~40 integer ops) + ~40 ALU; a time-phase uniform when drift != 0";
  s.inputs = {
      ports::color(ports::fixed("color", Type::Vec3, "the base water colour")),
      ports::fromBuiltin("normal", Type::Vec3, Builtin::Normal, "surface normal (normalised here)"),
      ports::fixed("sun", Type::Vec3, Value::vector({1, 1, -0.5}), "direction towards the sun (normalised here)"),
      ports::fixed("height", Type::Float, Value::scalar(0.5),
                   "wave height normalised to [0, 1] (0 trough, 1 crest; clamped)"),
      ports::fromBuiltin("position", Type::Vec3, Builtin::WorldPosition, "where the noise is sampled (x, z)"),
      ports::fixed("slope_strength", Type::Float, Value::scalar(0.2), "weight of the slope shift (the top-down water plan: 0.2)"),
      ports::fixed("noise_strength", Type::Float, Value::scalar(0.1),
                   "weight of the noise hue shift (the top-down water plan's u_colorNoiseStrength = 0.1)"),
      ports::fixed("trough", Type::Float, Value::scalar(0.15), "darkening at the trough (the top-down water plan: 0.15)"),
  };
  s.outputs = {ports::fixed("color", Type::Vec3, "the varied colour"),
               ports::fixed("noise", Type::Float, "the value noise in [0, 1)")};
  s.bypass = {{"color", "color", std::nullopt}, {"noise", "", Value::scalar(0)}};
  s.options = {
      ports::number("noise_scale", 0.02, 1e-6, 1e6, "noise frequency per world unit (the top-down water plan: 0.02)"),
      ports::number("drift", 0.05, 0.0, 1e3,
                    "noise drift in noise units per second (the top-down water plan: 0.05); wrapped exactly via a time phase"),
  };
  s.isSource = true;  // the drift reads a time phase
  s.parseOptions = optionParser(parseColorVariationOptions);
  s.emit = [](EmitContext& ctx) {
    const auto& [scale, drift] = ctx.options<ColorVariationOptions>();
    GlslExpr p = "(" + ctx.input("position") + ".xz * " + ctx.literal(scale) + ")";
    if (drift != 0.0)
      p = "(" + p + " + vec2(" + ctx.timePhase(variationDriftOmega(drift)) + " * " + ctx.literal(kNoisePeriod / glsl::kTau) + "))";
    GlslExpr noise = ctx.temporary(Type::Float, EmitContext::call("wg_color_variation_noise", {p}));
    ctx.output(0, EmitContext::call("wg_color_variation",
                                    {ctx.input("color"), ctx.input("normal"), ctx.input("sun"), ctx.input("height"),
                                     noise, ctx.input("slope_strength"), ctx.input("noise_strength"),
                                     ctx.input("trough")}));
    ctx.output(1, noise);
  };
  s.eval = [](EvalContext& ctx) {
    const auto& [scale, drift] = ctx.options<ColorVariationOptions>();
    const Value& pos = ctx.input("position");
    double offset = 0.0;
    if (drift != 0.0)
      offset = glsl::mod(variationDriftOmega(drift) * ctx.environment().time[0], glsl::kTau) * (kNoisePeriod / glsl::kTau);
    double noise = colorVariationNoise(pos[0] * scale + offset, pos[2] * scale + offset);
    ctx.output(0, colorVariationReference(ctx.input("color"), ctx.input("normal"), ctx.input("sun"), ctx.scalar("height"),
                                          noise, ctx.scalar("slope_strength"), ctx.scalar("noise_strength"),
                                          ctx.scalar("trough")));
    ctx.output(1, Value::scalar(noise));
  };
  s.tolerance = 1e-4;  // float32 fract of position * scale at 1e5 m keeps ~1e-4
  Value base = Value::vector({0.0, 0.3, 0.45});
  s.hardCases = {
      {"huge coordinates (1e5 m)", {{"color", base}, {"position", Value::vector({1e5, 0, -1e5})}}, {},
       "finite, near the base colour", -0.1, 0.6},
      {"huge coordinates (1e9 m)", {{"color", base}, {"position", Value::vector({1e9, 0, 1e9})}}, {},
       "wrapped before the int conversion: finite", -0.1, 0.6},
      {"zero normal and sun", {{"color", base}, {"normal", Value::vector({0, 0, 0})}, {"sun", Value::vector({0, 0, 0})}},
       {}, "facing 0: finite", -0.1, 0.6},
      {"height outside [0, 1]", {{"color", base}, {"height", Value::scalar(-7)}}, {}, "clamped: finite", -0.1, 0.6},
      {"noise in [0, 1)", {{"color", base}, {"position", Value::vector({-12.3, 0, 45.6})}}, {}, "noise in [0, 1)", 0, 1,
       "noise"},
  };
  return s;
}

}  // namespace wg::nodes
