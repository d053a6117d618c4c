// Depth and colour: absorption (Beer-Lambert with Pope & Fry's pure-water coefficients,
// or the deferred water article's relative-coefficient model) and haze (the deferred water article's distance blend to the
// background).
#include <cmath>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"
#include "nodes/shading_reference.h"

namespace wg::nodes {

namespace {

struct AbsorptionOptions {
  bool relative;  // the deferred water article's linear relative coefficients instead of Beer-Lambert
};
AbsorptionOptions parseAbsorptionOptions(const OptionReader& o) { return {o.is("model", "relative")}; }

}  // namespace

NodeSpec absorptionNode() {
  NodeSpec s;
  s.type = "absorption";
  s.family = "depth and colour";
  s.summary = "Light absorbed along a path through water, per colour channel: transmittance and the attenuated "
              "colour.";
  s.formula =
      "d = clamp(distance, 0, 1e30). beer_lambert: T = exp(-max(sigma, 0) d) per channel; pure water (Pope & Fry "
      "1997) sigma = (0.340, 0.0565, 0.00922) 1/m at 650/550/450 nm, so 10 m leave T = (0.0334, 0.5684, 0.9119). "
      "relative (the deferred water article): b = clamp((M - d) / M, 0, 1), g = clamp(b (1 - d k_g), 0, 1), r = clamp(b (1 - d k_r), "
      "0, 1), T = (r^2, g^2, b^2), M = max_distance. color = color_in * T; absorbed = 1 - T.";
  s.source = "deferred water article (listings 10-12: per-channel relative absorption over the in-water view distance, squared); "
             "Beer-Lambert coefficients from Pope & Fry 1997";
  s.cost = "beer_lambert: 3 exp2 (~8 ALU); relative: ~15 ALU, no transcendentals";
  s.inputs = {
      ports::fixed("distance", Type::Float, "path length through water in metres (e.g. water_depth.thickness)"),
      ports::color(ports::fixed("color", Type::Vec3, Value::vector({1, 1, 1}), "colour of the light entering the water path")),
      ports::fixed("sigma", Type::Vec3, Value::vector({0.340, 0.0565, 0.00922}),
                   "beer_lambert: absorption coefficients in 1/m (R, G, B; default pure water, Pope & Fry 1997)"),
      ports::fixed("max_distance", Type::Float, Value::scalar(220),
                   "relative: distance at which blue is gone (the deferred water article's InsideWaterMaxViewDistance; default fitted "
                   "to Pope & Fry at 5 m, as the source gives no number)"),
      ports::fixed("relative_red", Type::Float, Value::scalar(0.1125),
                   "relative: red's coefficient per metre (the deferred water article's RelativeAbsorbtionCoeffRed; fitted at 5 m)"),
      ports::fixed("relative_green", Type::Float, Value::scalar(0.0223),
                   "relative: green's coefficient per metre (RelativeAbsorbtionCoeffGreen; fitted at 5 m)"),
  };
  s.outputs = {ports::fixed("transmittance", Type::Vec3, "fraction of light left per channel, in [0, 1]"),
               ports::fixed("color", Type::Vec3, "color * transmittance"),
               ports::fixed("absorbed", Type::Vec3, "1 - transmittance (the deferred water article tints the water colour by it)")};
  s.options = {ports::choice("model", {"beer_lambert", "relative"}, "beer_lambert",
                             "exponential Beer-Lambert, or the deferred water article's linear relative coefficients, squared")};
  s.parseOptions = optionParser(parseAbsorptionOptions);
  s.emit = [](EmitContext& ctx) {
    bool relative = ctx.options<AbsorptionOptions>().relative;
    GlslExpr t = ctx.temporary(
        Type::Vec3, relative ? EmitContext::call("wg_absorption_relative",
                                                 {ctx.input("distance"), ctx.input("max_distance"),
                                                  ctx.input("relative_red"), ctx.input("relative_green")})
                             : EmitContext::call("wg_absorption_beer_lambert", {ctx.input("sigma"), ctx.input("distance")}));
    ctx.output(0, t);
    ctx.output(1, "(" + ctx.input("color") + " * " + t + ")");
    ctx.output(2, "(vec3(1.0) - " + t + ")");
  };
  s.eval = [](EvalContext& ctx) {
    bool relative = ctx.options<AbsorptionOptions>().relative;
    Value t = relative ? relativeAbsorptionReference(ctx.scalar("distance"), ctx.scalar("max_distance"),
                                                     ctx.scalar("relative_red"), ctx.scalar("relative_green"))
                       : beerLambertReference(ctx.input("sigma"), ctx.scalar("distance"));
    const Value& c = ctx.input("color");
    ctx.output(0, t);
    ctx.output(1, Value::vector({c[0] * t[0], c[1] * t[1], c[2] * t[2]}));
    ctx.output(2, Value::vector({1 - t[0], 1 - t[1], 1 - t[2]}));
  };
  s.tolerance = 1e-6;
  s.hardCases = {
      {"negative distance (scene in front)", {{"distance", Value::scalar(-5)}}, {}, "T = 1", 1, 1},
      {"sky distance 1e30", {{"distance", Value::scalar(1e30)}}, {}, "T = 0, not NaN", 0, 0},
      {"sky distance, relative model", {{"distance", Value::scalar(1e30)}}, {{"model", "relative"}}, "T = 0", 0, 0},
      {"negative coefficients", {{"distance", Value::scalar(10)}, {"sigma", Value::vector({-1, -1, -1})}}, {},
       "clamped to 0: T = 1", 1, 1},
      {"zero max distance", {{"distance", Value::scalar(1)}, {"max_distance", Value::scalar(0)}},
       {{"model", "relative"}}, "T = 0, finite", 0, 0},
  };
  return s;
}

NodeSpec hazeNode() {
  NodeSpec s;
  s.type = "haze";
  s.family = "depth and colour";
  s.summary = "Blends a colour towards the background by distance (the deferred water article's haze over 2000 units).";
  s.formula =
      "factor = clamp(distance / max(haze_distance, 1e-6), 0, 1) (the deferred water article: HazeValue = 1 - max(0, (2000 - d) * "
      "0.0005)); color = mix(color, background, factor).";
  s.source = "deferred water article (case 5 and listing 18: haze towards the background texture over 2000 units)";
  s.cost = "~5 ALU";
  s.inputs = {
      ports::color(ports::fixed("color", Type::Vec3, "the colour before haze")),
      ports::fixed("distance", Type::Float, "distance from the camera (e.g. water_depth.surface_distance)"),
      ports::color(ports::fixed("background", Type::Vec3, Value::vector({0.6, 0.7, 0.8}), "the haze / background colour")),
      ports::fixed("haze_distance", Type::Float, Value::scalar(2000), "distance at which only the background remains"),
  };
  s.outputs = {ports::fixed("color", Type::Vec3, "mix(color, background, factor)"),
               ports::fixed("factor", Type::Float, "the haze amount in [0, 1]")};
  s.emit = [](EmitContext& ctx) {
    GlslExpr f = ctx.temporary(Type::Float,
                                  EmitContext::call("wg_haze_factor", {ctx.input("distance"), ctx.input("haze_distance")}));
    ctx.output(0, EmitContext::call("mix", {ctx.input("color"), ctx.input("background"), f}));
    ctx.output(1, f);
  };
  s.eval = [](EvalContext& ctx) {
    double f = hazeFactorReference(ctx.scalar("distance"), ctx.scalar("haze_distance"));
    const Value &c = ctx.input("color"), &b = ctx.input("background");
    ctx.output(0, Value::vector({glsl::mix(c[0], b[0], f), glsl::mix(c[1], b[1], f), glsl::mix(c[2], b[2], f)}));
    ctx.output(1, Value::scalar(f));
  };
  s.tolerance = 1e-6;
  Value grey = Value::vector({0.5, 0.5, 0.5});
  s.hardCases = {
      {"sky distance 1e30", {{"color", grey}, {"distance", Value::scalar(1e30)}}, {}, "the background", 0, 1},
      {"negative distance", {{"color", grey}, {"distance", Value::scalar(-10)}}, {}, "the colour unchanged", 0, 1},
      {"zero haze distance", {{"color", grey}, {"distance", Value::scalar(0)}, {"haze_distance", Value::scalar(0)}}, {},
       "finite: factor 0 at distance 0", 0, 1},
  };
  return s;
}

}  // namespace wg::nodes
