// gerstner_waves: N Gerstner (trochoidal) waves displacing the surface, with the exact
// analytic normal, tangent and binormal of the displaced surface (the stylized water shader; GPU Gems 1,
// ch. 1). GPU Gems' eq. 12 evaluates the normal from per-wave terms, which is exact only
// for a single wave; here the partial derivatives dP/dx and dP/dz are summed over all
// waves and crossed, so the cross terms between waves are kept.
#include "core/emit_context.h"
#include "nodes/gerstner_waves.h"

#include <cmath>
#include <cstdio>

#include "nodes/eval_math.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"
#include "nodes/rounded_intermediates.h"
#include "nodes/waves_common.h"

namespace wg::nodes {
namespace {

using waves::D3;

std::string formatValue(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

bool finiteNumber(const nlohmann::json& v) { return v.is_number() && std::isfinite(v.get<double>()); }

}  // namespace

std::string validateGerstnerWaves(const nlohmann::json& v) {
  if (!v.is_array()) return "must be an array of waves ({\"direction\": [x, z], \"steepness\": Q, \"wavelength\": L})";
  if (v.empty()) return "must list at least one wave";
  if (v.size() > static_cast<size_t>(kMaxGerstnerWaves))
    return "lists " + std::to_string(v.size()) + " waves; at most " + std::to_string(kMaxGerstnerWaves) +
           " are allowed";
  double sum = 0;
  for (size_t i = 0; i < v.size(); ++i) {
    const auto& w = v[i];
    std::string where = "wave " + std::to_string(i) + ": ";
    if (!w.is_object()) return where + "must be an object";
    for (auto it = w.begin(); it != w.end(); ++it)
      if (it.key() != "direction" && it.key() != "steepness" && it.key() != "wavelength" && it.key() != "amplitude" &&
          it.key() != "phase")
        return where + "unknown key '" + it.key() + "' (expected direction, steepness, wavelength, amplitude, phase)";
    if (!w.contains("direction") || !w["direction"].is_array() || w["direction"].size() != 2 ||
        !finiteNumber(w["direction"][0]) || !finiteNumber(w["direction"][1]))
      return where + "'direction' must be two finite numbers [x, z]";
    double dx = w["direction"][0].get<double>(), dz = w["direction"][1].get<double>();
    if (dx * dx + dz * dz < 1e-12) return where + "'direction' must not be the zero vector";
    if (!w.contains("steepness") || !finiteNumber(w["steepness"])) return where + "'steepness' must be a finite number";
    double q = w["steepness"].get<double>();
    if (q < 0 || q > 1) return where + "'steepness' " + formatValue(q) + " is outside [0, 1]";
    if (!w.contains("wavelength") || !finiteNumber(w["wavelength"]))
      return where + "'wavelength' must be a finite number of metres";
    double lambda = w["wavelength"].get<double>();
    if (!(lambda > 0)) return where + "'wavelength' " + formatValue(lambda) + " must be greater than 0";
    double k = 2.0 * M_PI / lambda;
    // k and k A are shader constants and products: they must be float32 numbers (a
    // wavelength under ~1.8e-38 made k "inf", a literal glslang rejects).
    constexpr double kFloat32Max = 3.4028234663852886e38;
    if (!(k <= kFloat32Max))
      return where + "'wavelength' " + formatValue(lambda) + " is too small: 2 pi / wavelength exceeds float32 range";
    double a = q / k;
    if (w.contains("amplitude")) {
      if (!finiteNumber(w["amplitude"])) return where + "'amplitude' must be a finite number";
      a = w["amplitude"].get<double>();
      if (a < 0) return where + "'amplitude' " + formatValue(a) + " must not be negative";
      if (!(k * a <= kFloat32Max))
        return where + "'amplitude' " + formatValue(a) + " times 2 pi / wavelength exceeds float32 range";
    }
    if (w.contains("phase") && !finiteNumber(w["phase"])) return where + "'phase' must be a finite number";
    sum += q * k * a;
  }
  if (sum > 1.0 + 1e-9)
    return "the waves' steepness sum \xCE\xA3 Q\xC2\xB7k\xC2\xB7"
           "A = " +
           formatValue(sum) + " exceeds 1: the surface folds over";
  return "";
}

std::vector<GerstnerWave> parseGerstnerWaves(const nlohmann::json& v) {
  std::vector<GerstnerWave> out;
  for (const auto& w : v) {
    GerstnerWave g;
    double dx = w["direction"][0].get<double>(), dz = w["direction"][1].get<double>();
    double len = std::sqrt(dx * dx + dz * dz);
    g.dirX = dx / len;
    g.dirZ = dz / len;
    g.steepness = w["steepness"].get<double>();
    g.wavelength = w["wavelength"].get<double>();
    g.k = 2.0 * M_PI / g.wavelength;
    g.omega = std::sqrt(kGravity * g.k);
    g.amplitude = w.contains("amplitude") ? w["amplitude"].get<double>() : g.steepness / g.k;
    g.phase = w.contains("phase") ? w["phase"].get<double>() : 0.0;
    out.push_back(g);
  }
  return out;
}

GerstnerFrame gerstnerReference(const std::vector<GerstnerWave>& ws, double x, double z, double time) {
  GerstnerFrame f;
  for (const auto& w : ws) {
    double phase = w.phase - glsl::mod(w.omega * time, waves::kTwoPi);
    double theta = w.k * glsl::mod(w.dirX * x + w.dirZ * z, w.wavelength) + phase;
    double s = std::sin(theta), c = std::cos(theta);
    double qa = w.steepness * w.amplitude, ka = w.k * w.amplitude, qka = w.steepness * ka;
    f.displacement[0] += qa * w.dirX * c;
    f.displacement[1] += w.amplitude * s;
    f.displacement[2] += qa * w.dirZ * c;
    f.dPdx[0] += -qka * w.dirX * w.dirX * s;
    f.dPdx[1] += ka * w.dirX * c;
    f.dPdx[2] += -qka * w.dirX * w.dirZ * s;
    f.dPdz[0] += -qka * w.dirX * w.dirZ * s;
    f.dPdz[1] += ka * w.dirZ * c;
    f.dPdz[2] += -qka * w.dirZ * w.dirZ * s;
  }
  f.dPdx[0] += 1.0;
  f.dPdz[2] += 1.0;
  D3 n = waves::unitOr(waves::cross({f.dPdz[0], f.dPdz[1], f.dPdz[2]}, {f.dPdx[0], f.dPdx[1], f.dPdx[2]}), {0, 1, 0});
  if (n.y < 0) n = n * -1.0;
  f.normal[0] = n.x;
  f.normal[1] = n.y;
  f.normal[2] = n.z;
  return f;
}

// Each wave rounds its own phase argument D.(x, z) (two products, a sum, the mod's
// product: about 3 roundings of |Dx x| + |Dz z|). Moving the position cannot stand for
// that: the waves' slopes can cancel in the sum while their rounding errors add. So each
// wave's Dx and Dz are moved on their own (its phase by k r 2^-24 |Dx x|, ...).
std::vector<std::shared_ptr<const ParsedOptions>> gerstnerRoundedIntermediates(const ParsedOptions& options,
                                                                                double relative) {
  const auto& ws = options.as<std::vector<GerstnerWave>>();
  std::vector<std::shared_ptr<const ParsedOptions>> variants;
  for (size_t i = 0; i < ws.size(); ++i)
    for (double GerstnerWave::*component : {&GerstnerWave::dirX, &GerstnerWave::dirZ}) {
      if (ws[i].*component == 0.0) continue;
      std::vector<GerstnerWave> moved = ws;
      moved[i].*component *= 1.0 + relative;
      variants.push_back(std::make_shared<const OptionsOf<std::vector<GerstnerWave>>>(std::move(moved)));
    }
  return variants;
}

namespace {

// The `waves` option, parsed once into the waves the emitter and the reference iterate.
// Only the first `max_waves` of the list are summed (the quality knob: the list is ordered as
// the user wrote it, so the waves kept are the ones written first).
std::vector<GerstnerWave> parseGerstnerOptions(const OptionReader& o) {
  std::vector<GerstnerWave> ws = parseGerstnerWaves(o.json("waves"));
  size_t keep = static_cast<size_t>(o.integer("max_waves"));
  if (ws.size() > keep) ws.resize(keep);
  return ws;
}

}  // namespace

NodeSpec gerstnerWavesNode() {
  NodeSpec s;
  s.type = "gerstner_waves";
  s.family = "waves";
  s.summary = "Sum of Gerstner waves: displaced position with the exact analytic normal, tangent and binormal.";
  s.formula =
      "Per wave i: D = normalize(direction), k = 2 pi / wavelength, omega = sqrt(g k) (deep water, g = 9.81), "
      "A = amplitude (default Q/k), theta = k mod(D.(x,z), wavelength) - mod(omega t, 2 pi) + phase. "
      "P = p + sum(Q A Dx cos theta, A sin theta, Q A Dz cos theta). "
      "dP/dx = (1 - sum Q A k Dx^2 sin, sum A k Dx cos, -sum Q A k Dx Dz sin), "
      "dP/dz = (-sum Q A k Dx Dz sin, sum A k Dz cos, 1 - sum Q A k Dz^2 sin), all at the undisplaced point; "
      "normal = normalize(cross(dP/dz, dP/dx)) oriented up (y >= 0), tangent = normalize(dP/dx), "
      "binormal = normalize(dP/dz). Unlike GPU Gems eq. 12 (exact for one wave), the products of the sums keep "
      "the cross terms between waves. Degenerate vectors (a cusp, sum Q k A = 1) fall back to up, +x, +z. "
      "With the default amplitude A = Q/k the horizontal excursion is Q A = Q^2/k (the stylized water shader's code moves a = Q/k "
      "horizontally, i.e. its steepness acts on both); either way one wave reaches the cusp at Q = 1.";
  s.source =
      "stylized water shader (k = 2 pi / lambda, a = steepness / k, tangent and binormal; GPU Gems form of the sum), "
      "advanced shaders tutorial (vertex displacement whose normals the fragment stage must agree with)";
  s.cost =
      "per wave: one mod, sin and cos, ~20 ALU (a 16-wave maximum: ~330 ALU); normal: cross + inversesqrt. "
      "Each wave's time phase is one float uniform (computed in double by the runtime).";
  s.inputs = {ports::fromBuiltin("position", Type::Vec3, Builtin::WorldPosition,
                                 "the undisplaced surface point (world space, y up); in the fragment stage feed the "
                                 "undisplaced position, not the displaced one")};
  s.outputs = {ports::fixed("position", Type::Vec3, "the displaced point P"),
               ports::fixed("normal", Type::Vec3, "unit normal of the displaced surface, y >= 0"),
               ports::fixed("tangent", Type::Vec3, "unit dP/dx (the surface's x direction)"),
               ports::fixed("binormal", Type::Vec3, "unit dP/dz (the surface's z direction)")};
  s.options = {ports::checked(
      OptionSpec::Kind::Json, "waves", nlohmann::json::parse(R"([
    {"direction": [1, 0], "steepness": 0.5, "wavelength": 10},
    {"direction": [0, 1], "steepness": 0.25, "wavelength": 20},
    {"direction": [1, 1], "steepness": 0.15, "wavelength": 10}
  ])"),
      validateGerstnerWaves,
      "1 to 16 waves, each {\"direction\": [x, z] (normalised; not zero), \"steepness\": Q in [0, 1], "
      "\"wavelength\": metres > 0, \"amplitude\": metres (optional, default Q/k as in the stylized water shader), \"phase\": radians "
      "(optional)}. The sum of Q k A over the waves must not exceed 1, or the surface folds over."),
               ports::knob(ports::integer("max_waves", kMaxGerstnerWaves, 1, kMaxGerstnerWaves,
                                          "sum only the first this many waves of the list, in the order written "
                                          "(list the waves that matter most first); the default keeps every wave"),
                           {1, 2, 3, 4, 6, 8, 12, kMaxGerstnerWaves})};
  s.isSource = true;
  s.parseOptions = optionParser(parseGerstnerOptions);
  // wg_gerstner_normal and wg_waves_unit_or_vec3: unit, or a unit fallback when degenerate.
  s.facts = [](const std::vector<ValueFact>&, const ParsedOptions&) {
    return std::vector<ValueFact>{{}, ValueFact::unitVector(), ValueFact::unitVector(), ValueFact::unitVector()};
  };
  s.emit = [](EmitContext& ctx) {
    const auto& ws = ctx.options<std::vector<GerstnerWave>>();
    GlslExpr p = ctx.temporary(Type::Vec3, ctx.input("position"));
    GlslExpr xz = ctx.temporary(Type::Vec2, p + ".xz");
    GlslExpr acc = "mat3(0.0)";
    for (const auto& w : ws) {
      GlslExpr phase = "(" + ctx.literal(w.phase) + " - " + ctx.timePhase(w.omega) + ")";
      acc = ctx.temporary(Type::Mat3, EmitContext::call("wg_gerstner_wave_add",
                                                        {acc, xz, ctx.literal(Value::vector({w.dirX, w.dirZ})),
                                                         ctx.literal(w.k), ctx.literal(w.wavelength),
                                                         ctx.literal(w.amplitude), ctx.literal(w.steepness), phase}));
    }
    ctx.output(0, "(" + p + " + " + acc + "[0])");
    ctx.output(1, EmitContext::call("wg_gerstner_normal", {acc}));
    ctx.output(2, EmitContext::call("wg_waves_unit_or_vec3",
                                    {"(vec3(1.0, 0.0, 0.0) + " + acc + "[1])", "vec3(1.0, 0.0, 0.0)"}));
    ctx.output(3, EmitContext::call("wg_waves_unit_or_vec3",
                                    {"(vec3(0.0, 0.0, 1.0) + " + acc + "[2])", "vec3(0.0, 0.0, 1.0)"}));
  };
  s.eval = [](EvalContext& ctx) {
    const auto& ws = ctx.options<std::vector<GerstnerWave>>();
    const Value& p = ctx.input("position");
    GerstnerFrame f = gerstnerReference(ws, p[0], p[2], ctx.environment().time[0]);
    ctx.output(0, Value::vector({p[0] + f.displacement[0], p[1] + f.displacement[1], p[2] + f.displacement[2]}));
    ctx.output(1, Value::vector({f.normal[0], f.normal[1], f.normal[2]}));
    D3 t = waves::unitOr({f.dPdx[0], f.dPdx[1], f.dPdx[2]}, {1, 0, 0});
    D3 b = waves::unitOr({f.dPdz[0], f.dPdz[1], f.dPdz[2]}, {0, 0, 1});
    ctx.output(2, waves::value(t));
    ctx.output(3, waves::value(b));
  };
  // float32: phases k * mod(D.x, L) carry ~1e-6 relative error; positions of a few metres.
  s.tolerance = 1e-4;
  s.conditionRoundings = 4;
  s.conditionWhy = "grows with the phases k x of positions (float32 spacing 7.8 mm at 1e5 m), counted per wave, and at "
                   "the cusp, where the normal turns fast";
  // Each wave also rounds its own phase argument: gerstnerRoundedIntermediates below.
  auto cusp = nlohmann::json::parse(R"([{"direction": [1, 0], "steepness": 1, "wavelength": 8}])");
  auto threeAtCusp = nlohmann::json::parse(R"([
    {"direction": [1, 0], "steepness": 0.8, "wavelength": 8},
    {"direction": [1, 0], "steepness": 0.6, "wavelength": 8}])");
  s.hardCases = {
      {"cusp: one wave with Q = 1 on its crest (sum Q k A = 1)",
       {{"position", Value::vector({2, 0, 0})}},
       {{"waves", cusp}},
       "finite; the tangent vanishes there, so normal and tangent fall back to up and +x",
       -1,
       1,
       "normal"},
      {"two aligned waves summing to the cusp",
       {{"position", Value::vector({2, 0, 0})}},
       {{"waves", threeAtCusp}},
       "finite, unit normal",
       -1,
       1,
       "normal"},
      {"huge coordinates 1e5 m",
       {{"position", Value::vector({1e5, 0, -1e5})}},
       {},
       "finite: the phase is reduced by whole wavelengths before sin/cos",
       -1,
       1,
       "normal"},
      {"zero input position", {{"position", Value::vector({0, 0, 0})}}, {}, "finite, unit normal", -1, 1, "normal"},
  };
  return s;
}

}  // namespace wg::nodes
