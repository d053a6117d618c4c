// ocean_foam: the spectral ocean's persistent foam for the fragment stage: whitecaps that
// appear where the surface folds and fade over seconds after the crest has passed, kept
// per cascade by the simulation (core/ocean_foam.h) and read here at the still-water
// point, summed over the cascades with the readers' distance fade.
#include <algorithm>

#include "core/emit_context.h"
#include "core/ocean_settings.h"
#include "nodes/node_library.h"
#include "nodes/ocean_readers.h"
#include "nodes/port_builders.h"

namespace wg::nodes {

NodeSpec oceanFoamNode() {
  NodeSpec s;
  s.type = "ocean_foam";
  s.family = "waves";
  s.summary =
      "The spectral ocean's persistent foam at a still-water point, per pixel: it grows where "
      "the surface folds and decays over seconds (a feedback map the simulation steps).";
  s.formula =
      "per foam cascade f_(m+1) = min(1, f_m exp(-step / decay) + growth step max(0, threshold - J_c(t_(m+1)))) "
      "at t_m = m step, replayed from 0 at step n - ceil(5 decay / step) (n = floor(t / step)), and "
      "between f_n and f_(n+1) in time; foam = min(1, sum over c of w_c foam_c(p.xz)), w_c as "
      "ocean_displacement; J_c the cascade's own Jacobian. The rates are ocean_spectrum's foam_* options.";
  s.source = "Tessendorf, Simulating Ocean Water (2001); Jacobian foam as in Dupuy and Bruneton (2012)";
  s.cost =
      "per foam cascade 4 texel fetches and ~10 ALU; the simulation steps each foam cascade "
      "every foam_step seconds (evolution, 2 log2 N Stockham passes of one texture, one foam pass), "
      "and a still frame replays 5 decay times of steps";
  s.inputs = {ports::fixed("ocean", Type::Ocean, "the sea, from an ocean_spectrum node"),
              ports::fixed("position", Type::Vec3,
                           "the still water's point: ocean_displacement's `undisplaced` output"),
              ports::fromBuiltin("camera", Type::Vec3, Builtin::CameraPosition, "where distances are measured from")};
  s.outputs = {ports::fixed("foam", Type::Float, "foam cover in [0, 1]: 0 on clear water, 1 fully white")};
  s.options = {oceanread::fadeOption()};
  s.parseOptions = optionParser(oceanread::parseFade);
  s.isSource = true;
  s.facts = [](const std::vector<ValueFact>&, const ParsedOptions&) { return std::vector<ValueFact>{{}}; };
  s.emit = [](EmitContext& ctx) {
    const int ocean = ctx.inputIndex("ocean");
    const auto& settings = ctx.oceanSettings(ocean);
    GlslExpr p = ctx.temporary(Type::Vec3, ctx.input("position"));
    double fade = ctx.options<double>();
    std::vector<GlslExpr> w =
        oceanread::emitWeights(ctx, fade, fade > 0 ? "distance(" + p + ", " + ctx.input("camera") + ")" : "");
    GlslExpr sum;
    for (size_t c = 0; c < settings.cascades.tileLengths.size(); ++c) {
      if (!ocean::makesFoam(settings, static_cast<int>(c))) continue;
      const int n = ocean::cascadeResolution(settings.cascades, c);
      GlslExpr map = EmitContext::call(
          "wg_ocean_map", {ctx.oceanMap(ocean, static_cast<int>(c), ocean::kFoamMap), p + ".xz",
                           ctx.literal(n / settings.cascades.tileLengths[c]), std::to_string(n)}) + ".x";
      sum += (sum.empty() ? "" : " + ") + (w[c].empty() ? map : w[c] + " * " + map);
    }
    ctx.output(0, "min(" + sum + ", 1.0)");
  };
  s.eval = [](EvalContext& ctx) {
    const oceanread::EvalPoint at = oceanread::evalPoint(ctx);
    const ocean::OceanSettings& settings = oceanref::settingsOf(at.id);
    double sum = 0;
    for (size_t c = 0; c < at.weights.size(); ++c)
      if (ocean::makesFoam(settings, static_cast<int>(c)))
        sum += at.weights[c] *
               oceanref::sampleFoam(at.id, static_cast<int>(c), at.time, at.position[0], at.position[2]);
    ctx.output(0, Value::scalar(std::min(sum, 1.0)));
  };
  // The foam integrates the float32 Jacobian's error (~1e-5 on a rough sea) over the
  // steps with weight growth step / (1 - exp(-step / decay)), about growth x decay (4.5 by
  // default), and the float recurrence rounds once per step.
  s.tolerance = 1e-3;
  s.conditionRoundings = 4;
  s.conditionWhy =
      "the Jacobian's float32 error summed over the replayed steps with the foam's memory, growth x decay; "
      "where J crosses the threshold the foam's growth turns on and off";
  s.hardCases = {
      oceanread::hardCase("a calm (wind 0): no foam", Value::vector({3, 0, -7}),
                          oceanread::smallSea({{"wind_speed", 0}}), "foam = 0 exactly", 0, 0),
      oceanread::hardCase("a storm at 40 m/s with choppiness 4, where the surface folds", Value::vector({26, 0, 24.5}),
                          oceanread::smallSea({{"wind_speed", 40}, {"choppiness", 4}, {"fetch", 1000}}),
                          "foam has grown where the surface folds (0.85 at t = 0)", 0.1, 1),
      oceanread::hardCase("the same storm with foam_growth 1000, where the cover saturates", Value::vector({26, 0, 24.5}),
                          oceanread::smallSea({{"wind_speed", 40}, {"choppiness", 4}, {"fetch", 1000}, {"foam_growth", 1000}}),
                          "foam = 1 exactly: the clamp holds", 1, 1),
      oceanread::hardCase("100 km from the origin", Value::vector({1e5, 0, -1e5}), oceanread::smallSea(),
                          "foam in [0, 1]: the tiles repeat", 0, 1)};
  return s;
}

}  // namespace wg::nodes
