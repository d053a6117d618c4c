// subsurface: the fake subsurface scattering of the stylized water shader (section 8): light seen through
// the wave crests when the sun is behind them, a power of V.(-H) with H the light
// direction distorted by the normal, scaled by the wave height.
#include <cmath>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"
#include "nodes/shading_reference.h"

namespace wg::nodes {

NodeSpec subsurfaceNode() {
  NodeSpec s;
  s.type = "subsurface";
  s.family = "scattering";
  s.summary = "The stylized water shader's subsurface glow: light through the wave crests when the sun is behind them.";
  s.formula =
      "H = normalize(L + N * distortion); I = clamp(V.(-H), 0, 1)^power (safe pow) * clamp(height * 2 + 0.5, 0, "
      "1); intensity = I * strength; color = sss_color * intensity. N, V, L normalised safely.";
  s.source = "stylized water shader (section 8: H = normalize(lightDir + worldNormal * _SSSDistortion), pow(saturate(dot(viewDir, -H)), "
             "_SSSPower), waveHeightFactor = saturate(waveHeight * 2 + 0.5))";
  s.cost = "4 safe normalisations, exp2 + log2: ~30 ALU";
  s.inputs = {
      ports::fromBuiltin("normal", Type::Vec3, Builtin::Normal, "surface normal (normalised here)"),
      ports::fromBuiltin("view", Type::Vec3, Builtin::ViewDirection, "direction from the surface to the viewer"),
      ports::fixed("light", Type::Vec3, Value::vector({1, 1, -0.5}),
                   "direction from the surface towards the light (normalised here)"),
      ports::fixed("height", Type::Float, Value::scalar(0),
                   "wave height above the rest level (the stylized water shader: displaced y - original y)"),
      ports::fixed("distortion", Type::Float, Value::scalar(0.3),
                   "how far the normal bends the light direction (_SSSDistortion; the source gives no number)"),
      ports::fixed("power", Type::Float, Value::scalar(4), "exponent of the glow (_SSSPower)"),
      ports::fixed("strength", Type::Float, Value::scalar(1), "scale (_SSSStrength)"),
      ports::color(ports::fixed("color", Type::Vec3, Value::vector({0.0, 0.6, 0.5}), "the glow's colour (_SSSColor, greenish)")),
  };
  s.outputs = {ports::fixed("color", Type::Vec3, "color * intensity"),
               ports::fixed("intensity", Type::Float, "strength * V.(-H)^power * height factor")};
  s.bypass = {{"color", "", Value::vector({0, 0, 0})}, {"intensity", "", Value::scalar(0)}};
  s.emit = [](EmitContext& ctx) {
    bool known = ctx.inputFact("normal").normalized && ctx.inputFact("view").normalized &&
                 ctx.inputFact("light").normalized && ctx.inputFact("power").above(0);
    GlslExpr i = ctx.temporary(
        Type::Float, "(" + ctx.input("strength") + " * " +
                         EmitContext::call(known ? "wg_subsurface_intensity_unit" : "wg_subsurface_intensity",
                                           {ctx.input("normal"), ctx.input("view"), ctx.input("light"),
                                            ctx.input("distortion"), ctx.input("power"), ctx.input("height")}) +
                         ")");
    ctx.output(0, "(" + ctx.input("color") + " * " + i + ")");
    ctx.output(1, i);
  };
  s.eval = [](EvalContext& ctx) {
    double i = ctx.scalar("strength") *
               subsurfaceIntensityReference(ctx.input("normal"), ctx.input("view"), ctx.input("light"),
                                            ctx.scalar("distortion"), ctx.scalar("power"), ctx.scalar("height"));
    ctx.output(0, glsl::scale(ctx.input("color"), i));
    ctx.output(1, Value::scalar(i));
  };
  s.tolerance = 1e-5;
  auto up = Value::vector({0, 1, 0});
  s.hardCases = {
      {"light in front of the viewer", {{"view", Value::vector({0, 0.6, 0.8})}, {"light", Value::vector({0, 0.6, 0.8})}},
       {}, "0 (pow base 0)", 0, 0, "intensity"},
      {"light cancelled by the distortion (H = 0)",
       {{"normal", up}, {"light", Value::vector({0, -1, 0})}, {"distortion", Value::scalar(1)}}, {}, "0, not NaN", 0, 0,
       "intensity"},
      {"huge wave height", {{"height", Value::scalar(1e6)}, {"view", Value::vector({-1, 0, 0.5})}}, {},
       "height factor clamped to 1", 0, 1, "intensity"},
      {"power 0 at zero base", {{"power", Value::scalar(0)}, {"view", up}, {"light", up}}, {}, "pow(0, 0) = 1, finite", 0,
       1, "intensity"},
      {"zero-length vectors",
       {{"normal", Value::vector({0, 0, 0})}, {"view", Value::vector({0, 0, 0})}, {"light", Value::vector({0, 0, 0})}},
       {}, "0, not NaN", 0, 0, "intensity"},
  };
  return s;
}

}  // namespace wg::nodes
