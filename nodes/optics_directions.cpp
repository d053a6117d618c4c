// Optics, directions: reflect_dir (the mirror direction of the view ray) and refract_dir
// (Snell refraction with total internal reflection), the advanced shaders tutorial, parts 5 and 6.
#include <cmath>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"
#include "nodes/shading_reference.h"
#include "nodes/snell_constants.h"

namespace wg::nodes {

namespace {

struct RefractDirOptions {
  double eta;  // n_incident / n_transmitted: 1 / ior from air, ior from water
};
RefractDirOptions parseRefractDirOptions(const OptionReader& o) {
  double ior = o.number("ior");
  return {o.is("direction", "water_to_air") ? ior : 1.0 / ior};
}

}  // namespace

NodeSpec reflectDirNode() {
  NodeSpec s;
  s.type = "reflect_dir";
  s.family = "optics";
  s.summary = "Unit direction of the view ray mirrored about the surface normal (for reflection look-ups).";
  s.formula =
      "R = normalize(reflect(-V, N)) = normalize(2 (N.V) N - V), with N and V normalised first; every "
      "normalisation is the safe one (a zero vector stays zero, never NaN).";
  s.source = "advanced shaders tutorial (reflect(-V, N) for cube-map and planar reflection)";
  s.cost = "3 safe normalisations (inversesqrt) + reflect: ~15 ALU";
  s.inputs = {
      ports::fromBuiltin("normal", Type::Vec3, Builtin::Normal, "surface normal (normalised here)"),
      ports::fromBuiltin("view", Type::Vec3, Builtin::ViewDirection, "direction from the surface to the viewer"),
  };
  s.outputs = {ports::fixed("direction", Type::Vec3, "unit reflected direction, pointing away from the surface")};
  s.emit = [](EmitContext& ctx) {
    ctx.output(0, EmitContext::call("wg_reflect_dir", {ctx.input("normal"), ctx.input("view")}));
  };
  s.eval = [](EvalContext& ctx) { ctx.output(0, reflectDirReference(ctx.input("normal"), ctx.input("view"))); };
  s.tolerance = 1e-6;
  auto up = Value::vector({0, 1, 0});
  s.hardCases = {
      {"grazing view, N.V = 0", {{"normal", up}, {"view", Value::vector({1, 0, 0})}}, {}, "R = -V, unit", -1, 1},
      {"zero-length normal", {{"normal", Value::vector({0, 0, 0})}, {"view", up}}, {}, "R = -V, finite", -1, 1},
      {"both vectors zero", {{"normal", Value::vector({0, 0, 0})}, {"view", Value::vector({0, 0, 0})}}, {},
       "the zero vector, not NaN", 0, 0},
      {"unnormalised inputs", {{"normal", Value::vector({0, 1e6, 0})}, {"view", Value::vector({1e-6, 1e-6, 0})}}, {},
       "unit result", -1, 1},
  };
  return s;
}

NodeSpec refractDirNode() {
  NodeSpec s;
  s.type = "refract_dir";
  s.family = "optics";
  s.summary = "Snell refraction of the view ray through the surface; the mirror reflection under total internal "
              "reflection.";
  s.formula =
      "I = -V, c = clamp(N.V, 0, 1), eta = 1/ior (air_to_water) or ior (water_to_air), k = 1 - eta^2 (1 - c^2). "
      "The GLSL forms k as eta^2 (c^2 - cc^2), with eta^2 and the critical angle's squared cosine cc^2 = 1 - 1/eta^2 "
      "formed in double: exact near the critical angle. "
      "k >= 0: T = normalize(eta I + (eta c - sqrt(k)) N) (GLSL refract), tir = 0. k < 0 (from below past the "
      "critical angle asin(1/ior) = 48.6066 deg for 1.333): T = normalize(2 c N - V), the reflection, tir = 1.";
  s.source = "advanced shaders tutorial (refract(-V, N, 1.0 / 1.33), Snell's law)";
  s.cost = "3 safe normalisations + a sqrt and a branch: ~25 ALU";
  s.inputs = {
      ports::fromBuiltin("normal", Type::Vec3, Builtin::Normal, "surface normal facing the viewer (normalised here)"),
      ports::fromBuiltin("view", Type::Vec3, Builtin::ViewDirection, "direction from the surface to the viewer"),
  };
  s.outputs = {ports::fixed("direction", Type::Vec3, "unit refracted direction (the reflection under TIR)"),
               ports::fixed("tir", Type::Float, "1 under total internal reflection, else 0")};
  s.options = {
      ports::number("ior", 1.333, 1.0, 3.0, "index of refraction of water relative to air"),
      ports::choice("direction", {"air_to_water", "water_to_air"}, "air_to_water",
                    "the viewer's medium: from water the ray can be totally reflected"),
  };
  s.parseOptions = optionParser(parseRefractDirOptions);
  s.emit = [](EmitContext& ctx) {
    double eta = ctx.options<RefractDirOptions>().eta;
    SnellConstants snell = snellConstants(eta);
    GlslExpr t = ctx.temporary(
        Type::Vec4, EmitContext::call("wg_refract_dir", {ctx.input("normal"), ctx.input("view"), ctx.literal(eta),
                                                         ctx.literal(snell.eta2), ctx.literal(snell.cosCrit2)}));
    ctx.output(0, t + ".xyz");
    ctx.output(1, t + ".w");
  };
  s.eval = [](EvalContext& ctx) {
    Refraction r = refractDirReference(ctx.input("normal"), ctx.input("view"), ctx.options<RefractDirOptions>().eta);
    ctx.output(0, r.direction);
    ctx.output(1, Value::scalar(r.tir ? 1.0 : 0.0));
  };
  s.tolerance = 2e-6;
  // As fresnel: backward-stable in c = N.V; at the critical angle float32 cannot decide
  // between refraction and total reflection, and the conditioning term says so.
  s.conditionRoundings = 2;
  s.conditionWhy = "grows near the critical angle from below (water_to_air), where k = 1 - eta^2 (1 - c^2) passes 0 "
                   "with an infinite slope of sqrt(k): float32 rounding of N.V can flip the branch there";
  auto up = Value::vector({0, 1, 0});
  auto dirAt = [](double degrees) {
    double r = degrees * M_PI / 180.0;
    return Value::vector({std::sin(r), std::cos(r), 0});
  };
  s.hardCases = {
      {"grazing from air", {{"normal", up}, {"view", Value::vector({1, 0, 0})}}, {}, "unit direction, tir = 0", -1, 1},
      {"total internal reflection from below", {{"normal", up}, {"view", dirAt(60)}},
       {{"direction", "water_to_air"}}, "tir = 1, the reflection", 1, 1, "tir"},
      {"grazing from below", {{"normal", up}, {"view", Value::vector({1, 0, 0})}}, {{"direction", "water_to_air"}},
       "tir = 1, finite", 1, 1, "tir"},
      {"view behind the surface", {{"normal", up}, {"view", Value::vector({0.6, -0.8, 0})}}, {},
       "clamped to grazing, unit", -1, 1},
      {"zero-length normal", {{"normal", Value::vector({0, 0, 0})}, {"view", up}}, {}, "finite", -1, 1},
      {"both vectors zero", {{"normal", Value::vector({0, 0, 0})}, {"view", Value::vector({0, 0, 0})}},
       {{"direction", "water_to_air"}}, "the zero vector, not NaN", 0, 0},
  };
  return s;
}

}  // namespace wg::nodes
