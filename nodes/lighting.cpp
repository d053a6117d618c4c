// Optics, local lighting: lambert and blinn_phong (the advanced shaders tutorial, levels 1 and 2),
// phong_specular (the deferred water article's sun and environment Phong terms) and ggx_specular (the advanced shaders tutorial's
// Cook-Torrance with GGX D, Schlick F and Smith/Schlick-GGX G).
#include <cmath>
#include <optional>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/fresnel_reference.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"
#include "nodes/shading_reference.h"

namespace wg::nodes {
namespace {

// Towards the sun: the classic WebGL water renderer's sun travels along (-1, -1, 0.5), so the light lies at (1, 1, -0.5).
Value defaultSun() { return Value::vector({1, 1, -0.5}); }

PortSpec normalPort() {
  return ports::fromBuiltin("normal", Type::Vec3, Builtin::Normal, "surface normal (normalised here)");
}
PortSpec viewPort() {
  return ports::fromBuiltin("view", Type::Vec3, Builtin::ViewDirection, "direction from the surface to the viewer");
}
PortSpec lightPort(std::string name = "light") {
  return ports::fixed(std::move(name), Type::Vec3, defaultSun(),
                      "direction from the surface towards the light (normalised here); default the classic WebGL water renderer's sun");
}

Value scaled(const Value& c, double k) { return glsl::scale(c.convertedTo(Type::Vec3), k); }

const Value kUp = Value::vector({0, 1, 0});
const Value kZero = Value::vector({0, 0, 0});
// The sun a degree above the horizon behind the water, seen at half a degree: the glitter
// path of a low sun. L + V nearly cancels, so the half vector's direction carries the
// rounding of both, magnified about 40 times, into the sharp lobes of smooth water.
const Value kGlitterView = Value::vector({0.99996192306417131, 0.0087265354983739347, 0});
const Value kGlitterLight = Value::vector({-0.99984769515639127, 0.017452406437283512, 0});
// A normal so short that safe normalisation (dot floored at 1e-30) leaves it 0.9996 long:
// not unit, so the forms that hold only for unit vectors must not be taken.
const Value kShortNormal = Value::vector({0, 9.996e-16, 0});
// Why the half-vector lobes' bound follows their inputs' rounding (NodeSpec::conditionRoundings).
const char* const kHalfVectorConditioning =
    "grows where L + V nearly cancels (a low sun behind the water, seen at grazing: its glitter path): H = "
    "normalize(L + V) turns by the inputs' rounding divided by |L + V|, and a sharp lobe (high shininess, "
    "low roughness) magnifies that turn";

}  // namespace

NodeSpec lambertNode() {
  NodeSpec s;
  s.type = "lambert";
  s.family = "optics";
  s.summary = "Lambert diffuse lighting: N.L clamped to [0, 1].";
  s.formula = "intensity = clamp(dot(normalize(N), normalize(L)), 0, 1); color = light_color * surface_color * intensity.";
  s.source = "advanced shaders tutorial (Level 1: Lambert, NdotL = max(dot(N, L), 0))";
  s.cost = "2 safe normalisations + a dot: ~12 ALU";
  s.inputs = {normalPort(), lightPort(),
              ports::color(ports::fixed("light_color", Type::Vec3, Value::vector({1, 1, 1}), "colour of the light")),
              ports::color(ports::fixed("surface_color", Type::Vec3, Value::vector({1, 1, 1}), "diffuse colour of the surface"))};
  s.outputs = {ports::fixed("intensity", Type::Float, "N.L in [0, 1]"),
               ports::fixed("color", Type::Vec3, "light_color * surface_color * intensity")};
  s.emit = [](EmitContext& ctx) {
    GlslExpr i = ctx.temporary(Type::Float, EmitContext::call("wg_lambert", {ctx.input("normal"), ctx.input("light")}));
    ctx.output(0, i);
    ctx.output(1, "(" + ctx.input("light_color") + " * " + ctx.input("surface_color") + " * " + i + ")");
  };
  s.eval = [](EvalContext& ctx) {
    double i = lambertReference(ctx.input("normal"), ctx.input("light"));
    ctx.output(0, Value::scalar(i));
    const Value &lc = ctx.input("light_color"), &sc = ctx.input("surface_color");
    ctx.output(1, Value::vector({lc[0] * sc[0] * i, lc[1] * sc[1] * i, lc[2] * sc[2] * i}));
  };
  s.tolerance = 1e-6;
  s.hardCases = {
      {"light below the horizon", {{"normal", kUp}, {"light", Value::vector({0, -1, 0})}}, {}, "0", 0, 0},
      {"zero-length light", {{"normal", kUp}, {"light", kZero}}, {}, "0, not NaN", 0, 0},
      {"unnormalised, parallel", {{"normal", Value::vector({0, 1e5, 0})}, {"light", Value::vector({0, 1e-5, 0})}}, {},
       "1 (normalised first)", 0, 1},
  };
  return s;
}

NodeSpec blinnPhongNode() {
  NodeSpec s;
  s.type = "blinn_phong";
  s.family = "optics";
  s.summary = "Blinn-Phong lighting: a specular highlight from the half vector, plus Lambert diffuse.";
  s.formula =
      "H = normalize(L + V) (L and V more than 90 degrees apart: the sum's component along L - V, rounding of their "
      "lengths, removed); specular = strength * max(N.H, 0)^shininess (safe pow; within 0.1 rad of the peak "
      "formed as exp(shininess ln(1 - |N x H|^2) / 2), which keeps the digits N.H loses near 1); diffuse = max(N.L, 0); "
      "color = light_color * (surface_color * diffuse + specular).";
  s.source = "advanced shaders tutorial (Level 2: Blinn-Phong, shininess 32 / 64 / 128)";
  s.cost = "5 safe normalisations, a cross product, exp2 + log2: ~45 ALU";
  s.inputs = {normalPort(), viewPort(), lightPort(),
              ports::fixed("shininess", Type::Float, Value::scalar(64), "exponent: 8 soft, 64 medium, 256 sharp"),
              ports::fixed("strength", Type::Float, Value::scalar(1), "specular strength"),
              ports::color(ports::fixed("light_color", Type::Vec3, Value::vector({1, 1, 1}), "colour of the light")),
              ports::color(ports::fixed("surface_color", Type::Vec3, Value::vector({0, 0, 0}),
                                        "diffuse colour (black: the specular highlight alone)"))};
  s.outputs = {ports::fixed("specular", Type::Float, "strength * max(N.H, 0)^shininess"),
               ports::fixed("diffuse", Type::Float, "max(N.L, 0)"),
               ports::fixed("color", Type::Vec3, "light_color * (surface_color * diffuse + specular)")};
  s.emit = [](EmitContext& ctx) {
    GlslExpr sp = ctx.temporary(
        Type::Float, "(" + ctx.input("strength") + " * " +
                         EmitContext::call("wg_blinn_phong_specular", {ctx.input("normal"), ctx.input("view"),
                                                                       ctx.input("light"), ctx.input("shininess")}) +
                         ")");
    GlslExpr di = ctx.temporary(Type::Float, EmitContext::call("wg_lambert", {ctx.input("normal"), ctx.input("light")}));
    ctx.output(0, sp);
    ctx.output(1, di);
    ctx.output(2, "(" + ctx.input("light_color") + " * (" + ctx.input("surface_color") + " * " + di + " + " + sp + "))");
  };
  s.eval = [](EvalContext& ctx) {
    double sp = ctx.scalar("strength") * blinnPhongSpecularReference(ctx.input("normal"), ctx.input("view"),
                                                                     ctx.input("light"), ctx.scalar("shininess"));
    double di = lambertReference(ctx.input("normal"), ctx.input("light"));
    ctx.output(0, Value::scalar(sp));
    ctx.output(1, Value::scalar(di));
    const Value &lc = ctx.input("light_color"), &sc = ctx.input("surface_color");
    Value c = Value::ofType(Type::Vec3);
    for (int i = 0; i < 3; ++i) c[i] = lc[i] * (sc[i] * di + sp);
    ctx.output(2, c);
  };
  s.tolerance = 1e-5;
  s.conditionRoundings = 2;
  s.conditionWhy = kHalfVectorConditioning;
  s.hardCases = {
      {"light opposite the viewer (H = 0)", {{"normal", kUp}, {"view", kUp}, {"light", Value::vector({0, -1, 0})}}, {},
       "0, not NaN", 0, 0},
      {"low sun behind the water, grazing view (glitter)",
       {{"normal", kUp}, {"view", kGlitterView}, {"light", kGlitterLight}, {"shininess", Value::scalar(2048)}}, {},
       "near the lobe's peak, within the bound its inputs' rounding allows", 0, 1},
      {"normal just under the normalisation floor", {{"normal", kShortNormal}, {"view", kUp}, {"light", kUp}}, {},
       "safe-normalised to length 0.9996, not 1: the textbook power, as the reference", 0, 1},
      {"shininess 0 with N.H = 0", {{"normal", Value::vector({1, 0, 0})}, {"view", kUp}, {"light", kUp},
                                    {"shininess", Value::scalar(0)}}, {}, "pow base 0: 1, finite", 0, 1},
      {"grazing view, huge shininess", {{"normal", kUp}, {"view", Value::vector({1, 0, 0})},
                                        {"shininess", Value::scalar(1e6)}}, {}, "0, finite", 0, 1},
      {"zero-length normal", {{"normal", kZero}}, {}, "0, finite", 0, 1},
  };
  return s;
}

NodeSpec phongSpecularNode() {
  NodeSpec s;
  s.type = "phong_specular";
  s.family = "optics";
  s.summary = "The deferred water article's Phong specular reflection of the sun and of the environment light.";
  s.formula =
      "R(L) = 2 (N.L) N - L (L mirrored about N; equivalently the view ray reflected, reflect(-V, N).L); "
      "sun = clamp(R(sun).V, 0, 1)^shine (safe pow); environment = clamp(R(environment).V, 0, 1) (no exponent, "
      "as in the deferred water article); color = sun * sun_color + environment * environment_color.";
  s.source = "deferred water article (listing 9: SpecularIntensity = pow(max(-dot(2 (N.L) N - L, camera-to-surface), 0), LightColor.w), "
             "EnvironmentSpecularIntensity likewise without exponent); shine 20 from the classic WebGL water renderer's shineDamper";
  s.cost = "6 safe normalisations, exp2 + log2: ~40 ALU";
  s.inputs = {normalPort(), viewPort(), lightPort("sun"),
              ports::fixed("shine", Type::Float, Value::scalar(20), "sun exponent (the deferred water article's LightColor.w, the classic WebGL water renderer's "
                                                                   "shineDamper = 20)"),
              ports::color(ports::fixed("sun_color", Type::Vec3, Value::vector({1, 1, 1}), "colour of the sun light")),
              ports::fixed("environment", Type::Vec3, kUp, "direction towards the environment light (the sky)"),
              ports::color(ports::fixed("environment_color", Type::Vec3, Value::vector({0.3, 0.35, 0.4}),
                                        "colour of the environment light"))};
  s.outputs = {ports::fixed("sun_specular", Type::Float, "the sun's specular intensity in [0, 1]"),
               ports::fixed("environment_specular", Type::Float, "the environment's specular intensity in [0, 1]"),
               ports::fixed("color", Type::Vec3, "sun * sun_color + environment * environment_color")};
  // The lobe lies in [0, 1]; its safe power stays there only for shine >= 0 (x^s >= 1 for
  // s < 0). The environment term has no exponent.
  s.facts = [](const std::vector<ValueFact>& in, const ParsedOptions&) {
    ValueFact unitRange{0, 1, false};
    const ValueFact& shine = in[3];
    return std::vector<ValueFact>{shine.atLeast(0) ? unitRange : ValueFact{}, unitRange, {}};
  };
  s.emit = [](EmitContext& ctx) {
    // Normalized inputs need no re-normalisation; the lobe lies in [0, 1], so a proven
    // shine > 0 makes native pow defined and equal to the safe one.
    bool unitNV = ctx.inputFact("normal").normalized && ctx.inputFact("view").normalized;
    auto lobe = [&](const char* light) {
      bool unit = unitNV && ctx.inputFact(light).normalized;
      return EmitContext::call(unit ? "wg_phong_specular_lobe_unit" : "wg_phong_specular_lobe",
                               {ctx.input("normal"), ctx.input("view"), ctx.input(light)});
    };
    std::string pow = ctx.inputFact("shine").above(0) ? "wg_pow_known_safe_float" : "wg_safe_pow_float";
    GlslExpr sun = ctx.temporary(Type::Float, EmitContext::call(pow, {lobe("sun"), ctx.input("shine")}));
    GlslExpr env = ctx.temporary(Type::Float, lobe("environment"));
    ctx.output(0, sun);
    ctx.output(1, env);
    ctx.output(2, "(" + sun + " * " + ctx.input("sun_color") + " + " + env + " * " + ctx.input("environment_color") + ")");
  };
  s.eval = [](EvalContext& ctx) {
    double sun = glsl::safePow(phongSpecularLobeReference(ctx.input("normal"), ctx.input("view"), ctx.input("sun")),
                               ctx.scalar("shine"));
    double env = phongSpecularLobeReference(ctx.input("normal"), ctx.input("view"), ctx.input("environment"));
    ctx.output(0, Value::scalar(sun));
    ctx.output(1, Value::scalar(env));
    const Value &sc = ctx.input("sun_color"), &ec = ctx.input("environment_color");
    ctx.output(2, Value::vector({sun * sc[0] + env * ec[0], sun * sc[1] + env * ec[1], sun * sc[2] + env * ec[2]}));
  };
  s.tolerance = 1e-5;
  s.hardCases = {
      {"sun behind the viewer's reflection", {{"normal", kUp}, {"view", kUp}, {"sun", Value::vector({0, -1, 0})}}, {},
       "0 (pow base 0)", 0, 0},
      {"grazing view", {{"normal", kUp}, {"view", Value::vector({1, 0, 0})}}, {}, "finite, in [0, 1]", 0, 1},
      {"zero-length vectors", {{"normal", kZero}, {"view", kZero}, {"sun", kZero}}, {}, "0, not NaN", 0, 0},
      {"shine 0", {{"normal", kUp}, {"view", Value::vector({1, 0, 0})}, {"shine", Value::scalar(0)}}, {},
       "pow(0, 0) = 1, finite", 0, 1},
  };
  return s;
}

NodeSpec ggxSpecularNode() {
  NodeSpec s;
  s.type = "ggx_specular";
  s.family = "optics";
  s.summary = "Cook-Torrance microfacet specular: GGX distribution, Schlick Fresnel (F0 = 0.02), Smith/Schlick-GGX "
              "geometry.";
  s.formula =
      "H = normalize(L + V) (as blinn_phong's), a = r^2 with r = clamp(roughness, 0.001, 1); D = a^2 / (pi (NdotH^2 a^2 + 1 - NdotH^2)^2) "
      "(GGX / Trowbridge-Reitz; the shader forms 1 - NdotH^2 as |N x H|^2, which keeps its bits where H is near N); F = F0 + (1 - F0)(1 - V.H)^5; G = G1(N.L) G1(N.V), G1(x) = x / (x (1 - k) + k), "
      "k = (r + 1)^2 / 8. brdf = D F G / (4 NdotL NdotV), computed as D F / (4 (NdotL (1 - k) + k)(NdotV (1 - k) + k)): "
      "identical where NdotL, NdotV > 0 and its finite limit where either is 0, so nothing divides by zero. "
      "specular = brdf * NdotL; color = light_color * specular. All dots clamped to [0, 1]. With slope_variance "
      "V > 0 (clamped to 1e4), the lobe filtered over facets whose slopes spread around N with total variance V: "
      "a' = a^2 + V, w = a^2 / a', D = w GGX(a') + (1 - w) Beckmann(a') with Beckmann(a') = exp(-tan^2 / a') / (pi "
      "a' cos^4) at N.H; the reflecting facets' normal N* = normalize(w (N.H) N + (1 - w) H); brdf = D (N.H / N*.H) "
      "F / (4 (N*.L (1 - k) + k)(N*.V (1 - k) + k)) with k of r (the base roughness); specular = brdf * N*.L.";
  s.source = "advanced shaders tutorial (Level 3: Cook-Torrance, DistributionGGX, FresnelSchlick with F0 = 0.02, GeometrySmith; water "
             "roughness ~0.05); the filtered lobe: Olano and Baker, LEAN Mapping (2010), a Gaussian spread of slopes "
             "convolved with a Beckmann lobe";
  s.cost = "5 safe normalisations, a cross product, 3 divisions: ~60 ALU; with a slope variance ~100 ALU and an exp";
  s.inputs = {normalPort(), viewPort(), lightPort(),
              ports::fixed("roughness", Type::Float, Value::scalar(0.05),
                           "perceptual roughness (water ~0.05); clamped to [0.001, 1]"),
              ports::fixed("f0", Type::Float, Value::scalar(0.02), "reflectance at normal incidence (water 0.02)"),
              ports::color(ports::fixed("light_color", Type::Vec3, Value::vector({1, 1, 1}), "colour (radiance) of the light")),
              ports::fixed("slope_variance", Type::Float, Value::scalar(0),
                           "variance of the surface's slopes around the normal that the normal does not carry (both "
                           "axes' summed; ocean_surface's `variance`, what its filter averages away over the pixel): "
                           "the lobe becomes the base lobe spread by it, keeping the pixel's mean radiance; 0: the "
                           "plain lobe. Clamped to [0, 1e4]")};
  s.outputs = {ports::fixed("specular", Type::Float, "brdf * NdotL: reflected radiance per unit light"),
               ports::fixed("brdf", Type::Float, "D F G / (4 NdotL NdotV)"),
               ports::fixed("distribution", Type::Float, "the GGX term D (at most 1 / (pi a^2) = 3.2e11)"),
               ports::fixed("fresnel", Type::Float, "the Schlick term F"),
               ports::fixed("color", Type::Vec3, "light_color * specular")};
  s.emit = [](EmitContext& ctx) {
    // A variance of constant 0 (the default) is the plain lobe: no filtered function in the text.
    const std::optional<Value> spread = ctx.inputConstant(ctx.inputIndex("slope_variance"));
    GlslExpr t = ctx.temporary(
        Type::Vec4, spread && (*spread)[0] == 0
                        ? EmitContext::call("wg_ggx_specular", {ctx.input("normal"), ctx.input("view"), ctx.input("light"),
                                                                ctx.input("roughness"), ctx.input("f0")})
                        : EmitContext::call("wg_ggx_specular_filtered",
                                            {ctx.input("normal"), ctx.input("view"), ctx.input("light"),
                                             ctx.input("roughness"), ctx.input("slope_variance"), ctx.input("f0")}));
    GlslExpr sp = ctx.temporary(Type::Float, "(" + t + ".x * " + t + ".w)");
    ctx.output(0, sp);
    ctx.output(1, t + ".x");
    ctx.output(2, t + ".y");
    ctx.output(3, t + ".z");
    ctx.output(4, "(" + ctx.input("light_color") + " * " + sp + ")");
  };
  s.eval = [](EvalContext& ctx) {
    GgxTerms g = ggxSpecularFilteredReference(ctx.input("normal"), ctx.input("view"), ctx.input("light"),
                                              ctx.scalar("roughness"), ctx.scalar("slope_variance"), ctx.scalar("f0"));
    double sp = g.brdf * g.ndotl;
    ctx.output(0, Value::scalar(sp));
    ctx.output(1, Value::scalar(g.brdf));
    ctx.output(2, Value::scalar(g.d));
    ctx.output(3, Value::scalar(g.f));
    ctx.output(4, scaled(ctx.input("light_color"), sp));
  };
  s.tolerance = 1e-5;  // relative: D reaches 3.2e11 at roughness 0.001; float32 keeps ~1e-6 of it
  s.conditionRoundings = 2;
  s.conditionWhy = kHalfVectorConditioning;
  Value grazing = Value::vector({1, 0, 0});
  s.hardCases = {
      {"N.V = 0 (grazing view)", {{"normal", kUp}, {"view", grazing}}, {}, "finite, >= 0", 0, 1e12},
      {"N.L = 0 (grazing light)", {{"normal", kUp}, {"view", kUp}, {"light", grazing}}, {}, "specular 0", 0, 0},
      {"mirror smooth at the highlight", {{"normal", kUp}, {"view", kUp}, {"light", kUp},
                                          {"roughness", Value::scalar(0)}}, {},
       "D = 1 / (pi 1e-12): large but finite", 0, 1e12},
      {"light opposite the viewer (H = 0)", {{"normal", kUp}, {"view", grazing}, {"light", Value::vector({-1, 0, 0})}},
       {}, "finite", 0, 1e12},
      {"low sun behind the water, grazing view (glitter)", {{"normal", kUp}, {"view", kGlitterView}, {"light", kGlitterLight}},
       {}, "D near its peak (H within a degree of N), within the bound its inputs' rounding allows", 0, 1e12},
      {"normal just under the normalisation floor", {{"normal", kShortNormal}, {"view", kUp}, {"light", kUp}}, {},
       "safe-normalised to length 0.9996, not 1: the textbook D of that vector, as the reference", 0, 1e12},
      {"zero-length vectors", {{"normal", kZero}, {"view", kZero}, {"light", kZero}}, {}, "0, not NaN", 0, 0},
      {"roughness above 1", {{"roughness", Value::scalar(5)}}, {}, "clamped to 1, finite", 0, 1e12},
      {"filtered: mirror smooth at the highlight with slope variance 0.02",
       {{"normal", kUp}, {"view", kUp}, {"light", kUp}, {"roughness", Value::scalar(0)},
        {"slope_variance", Value::scalar(0.02)}}, {},
       "D = 1 / (pi (1e-12 + 0.02)) = 15.9, the spread's peak, not the smooth base's 3.2e11", 0, 1e12},
      {"filtered: grazing view (N.V = 0)", {{"normal", kUp}, {"view", grazing}, {"slope_variance", Value::scalar(0.03)}},
       {}, "finite, >= 0", 0, 1e12},
      {"filtered: slope variance 1e6", {{"slope_variance", Value::scalar(1e6)}}, {}, "clamped to 1e4, finite", 0, 1e12},
      {"filtered: negative slope variance", {{"slope_variance", Value::scalar(-0.5)}}, {},
       "clamped to 0: the plain lobe", 0, 1e12},
  };
  return s;
}

}  // namespace wg::nodes
