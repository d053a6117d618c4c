// fresnel: how much of the light the water surface reflects, by viewing angle. Models:
// `schlick` (the advanced shaders tutorial, F0 = 0.02), `exact` dielectric Fresnel with an index of refraction,
// and `power` (the classic WebGL water renderer's (N.V)^strength and the stylized water shader's (1 - N.V)^strength). Seen from
// below (`water_to_air`), light beyond the critical angle is totally reflected.
#include <cmath>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/fresnel_reference.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"
#include "nodes/snell_constants.h"

namespace wg::nodes {
namespace {

FresnelSetup parseFresnelOptions(const OptionReader& o) {
  return {o.choice<FresnelModel>("model", {{"schlick", FresnelModel::Schlick},
                                           {"exact", FresnelModel::Exact},
                                           {"power", FresnelModel::Power}}),
          o.is("direction", "water_to_air"), o.number("ior"), o.is("power_form", "one_minus_cos")};
}

}  // namespace

NodeSpec fresnelNode() {
  NodeSpec s;
  s.type = "fresnel";
  s.family = "optics";
  s.summary = "Fresnel reflectance of the water surface by viewing angle (and its complement, the transmittance).";
  s.formula =
      "c = clamp(dot(N, V), 0, 1). schlick: F = F0 + (1 - F0)(1 - c)^5, from below with the transmitted cosine "
      "(F = 1 past the critical angle). exact: F = (Rs^2 + Rp^2) / 2 with Rs = (n1 c - n2 ct)/(n1 c + n2 ct), "
      "Rp = (n1 ct - n2 c)/(n1 ct + n2 c), ct = sqrt(1 - (n1/n2)^2 (1 - c^2)), F = 1 under total internal "
      "reflection (ct^2 <= 0). The GLSL forms ct^2 as eta^2 (c^2 - cc^2), eta = n1/n2, with eta^2 and the critical "
      "angle's squared cosine cc^2 = 1 - 1/eta^2 formed in double: exact near the critical angle. power: F = 1 - c^strength (form cos, the classic WebGL water renderer) or (1 - c)^strength (form one_minus_cos, "
      "the stylized water shader). transmittance = 1 - F.";
  s.source = "classic WebGL water renderer (power, strength 2), advanced shaders tutorial (Schlick, F0 = 0.02), stylized water shader (power of 1 - N.V)";
  s.cost = "schlick ~6 ALU; exact ~20 ALU and a sqrt; power: exp2 + log2";
  s.inputs = {
      ports::fromBuiltin("normal", Type::Vec3, Builtin::Normal, "unit surface normal facing the viewer"),
      ports::fromBuiltin("view", Type::Vec3, Builtin::ViewDirection, "unit vector from the surface to the viewer"),
      ports::fixed("f0", Type::Float, Value::scalar(0.02), "reflectance at normal incidence (schlick)"),
      ports::fixed("strength", Type::Float, Value::scalar(2.0), "exponent of the power model"),
  };
  s.outputs = {ports::fixed("reflectance", Type::Float, "F, in [0, 1]"),
               ports::fixed("transmittance", Type::Float, "1 - F")};
  s.options = {
      ports::knob(ports::choice("model", {"schlick", "exact", "power"}, "schlick", "which formula"),
                  {"power", "schlick", "exact"}),
      ports::choice("direction", {"air_to_water", "water_to_air"}, "air_to_water",
                    "the viewer's medium: from below, total internal reflection past the critical angle "
                    "(schlick, exact)"),
      ports::number("ior", 1.333, 1.0, 3.0, "index of refraction of water relative to air"),
      ports::choice("power_form", {"cos", "one_minus_cos"}, "cos",
                    "power model: 1 - (N.V)^strength (the classic WebGL water renderer) or (1 - N.V)^strength (the stylized water shader)"),
  };
  s.parseOptions = optionParser(parseFresnelOptions);
  // F in [0, 1] only where the inputs keep it there: schlick needs f0 in [0, 1]; the power
  // forms need strength >= 0 (c^s >= 1 for s < 0); exact always is.
  s.facts = [](const std::vector<ValueFact>& in, const ParsedOptions& options) {
    FresnelModel model = options.as<FresnelSetup>().model;
    const ValueFact &f0 = in[2], &strength = in[3];
    bool bounded = model == FresnelModel::Exact || (model == FresnelModel::Schlick && f0.atLeast(0) && f0.hi <= 1) ||
                   (model == FresnelModel::Power && strength.atLeast(0));
    if (!bounded) return std::vector<ValueFact>{{}, {}};
    return std::vector<ValueFact>{{0, 1, false}, {0, 1, false}};
  };
  s.emit = [](EmitContext& ctx) {
    const FresnelSetup& o = ctx.options<FresnelSetup>();
    bool below = o.fromBelow;
    double ior = o.ior;
    GlslExpr c = ctx.temporary(Type::Float, EmitContext::call("wg_cos_incidence", {ctx.input("normal"), ctx.input("view")}));
    GlslExpr f;
    // Snell's constants for the viewer's side, eta = n_viewer / n_other.
    SnellConstants snell = snellConstants(below ? ior : 1.0 / ior);
    GlslExpr eta2 = ctx.literal(snell.eta2), cosCrit2 = ctx.literal(snell.cosCrit2);
    if (o.model == FresnelModel::Schlick) {
      f = below ? EmitContext::call("wg_fresnel_schlick_from_below", {c, ctx.input("f0"), eta2, cosCrit2})
                : EmitContext::call("wg_fresnel_schlick", {c, ctx.input("f0")});
    } else if (o.model == FresnelModel::Exact) {
      f = below ? EmitContext::call("wg_fresnel_exact", {c, ctx.literal(ior), "1.0", eta2, cosCrit2})
                : EmitContext::call("wg_fresnel_exact", {c, "1.0", ctx.literal(ior), eta2, cosCrit2});
    } else {
      bool rim = o.rim;
      // strength > 0 proven: native pow (the base lies in [0, 1]).
      std::string fn = rim ? "wg_fresnel_power_rim" : "wg_fresnel_power_cos";
      if (ctx.inputFact("strength").above(0)) fn += "_positive";
      f = EmitContext::call(fn, {c, ctx.input("strength")});
    }
    GlslExpr r = ctx.temporary(Type::Float, f);
    ctx.output(0, r);
    ctx.output(1, "(1.0 - " + r + ")");
  };
  s.eval = [](EvalContext& ctx) {
    double c = glsl::saturate(glsl::dot(ctx.input("normal"), ctx.input("view")));
    double f = fresnelReference(ctx.options<FresnelSetup>(), c, ctx.scalar("f0"), ctx.scalar("strength"));
    ctx.output(0, Value::scalar(f));
    ctx.output(1, Value::scalar(1.0 - f));
  };
  s.tolerance = 2e-6;
  // Backward-stable in c = N.V: the float32 error stays within what rounding c by 2^-23
  // relative makes of F (measured 0.1 of it near the critical angle).
  s.conditionRoundings = 2;
  s.conditionWhy =
      "grows as |dF/dc| |c| near the critical angle from below (water_to_air), where sqrt(1 - n^2 sin^2) has an "
      "infinite slope: float32 rounding of N.V alone moves F there by up to 1e-3";
  auto up = Value::vector({0, 1, 0});
  auto dirAt = [](double degrees) {
    double r = degrees * M_PI / 180.0;
    return Value::vector({std::sin(r), std::cos(r), 0});
  };
  s.hardCases = {
      {"grazing view, N.V = 0", {{"normal", up}, {"view", Value::vector({1, 0, 0})}}, {{"model", "exact"}}, "F = 1, finite", 0, 1},
      {"view slightly below the surface", {{"normal", up}, {"view", Value::vector({1, -1e-4, 0})}},
       {{"model", "schlick"}}, "clamped to grazing: F = 1", 0, 1},
      {"N.V = 1.0000001 (unnormalised)", {{"normal", up}, {"view", Value::vector({0, 1.0000001, 0})}},
       {{"model", "exact"}}, "clamped to normal incidence: F = 0.0204", 0, 1},
      {"total internal reflection from below", {{"normal", up}, {"view", dirAt(60)}},
       {{"model", "exact"}, {"direction", "water_to_air"}}, "F = 1", 1, 1},
      {"exactly the critical angle", {{"normal", up}, {"view", dirAt(48.6066)}},
       {{"model", "schlick"}, {"direction", "water_to_air"}}, "F in [0, 1], finite", 0, 1},
      {"zero-length normal", {{"normal", Value::vector({0, 0, 0})}, {"view", up}}, {{"model", "exact"}},
       "treated as grazing: F = 1", 0, 1},
      {"power with zero base", {{"normal", up}, {"view", up}}, {{"model", "power"}, {"power_form", "one_minus_cos"}},
       "0^strength = 0, not NaN", 0, 0},
  };
  return s;
}

}  // namespace wg::nodes
