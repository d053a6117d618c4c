// coastal_foam: the deferred water article's shore foam, the shallow-depth amount (or crest foam fed in)
// times a foam texture distorted by the surface normal, and its dimming of the specular.
#include <algorithm>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/foam_caustics_reference.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"

namespace wg::nodes {

// As nodes/glsl/coastal_foam.glsl.
double coastalFoamAmount(double depth, double maxDepth, double intensity, double crest) {
  double r = glsl::saturate(depth / std::max(maxDepth, 1e-6));
  return std::max(std::max(0.0, intensity * (1.0 - r)), crest);
}
double coastalFoamSpecular(double foam, double k, bool cubic) {
  double s = glsl::saturate(1.0 - k * foam);
  return cubic ? s * s * s : s;
}

namespace {

struct CoastalFoamOptions {
  bool cubic;  // specular dimming by (1 - foam)^3 rather than linearly
};
CoastalFoamOptions parseCoastalFoamOptions(const OptionReader& o) { return {o.is("dimming", "cubic")}; }

}  // namespace

NodeSpec coastalFoamNode() {
  NodeSpec s;
  s.type = "coastal_foam";
  s.family = "foam";
  s.summary = "Shore foam from the water depth (and optional crest foam) times a normal-distorted foam texture; dims the specular.";
  s.formula =
      "uv = (tex_scale x + 0.5, 0.5 - tex_scale z) + distortion (N.x, N.z); amount = max(intensity (1 - clamp(depth / "
      "max_depth, 0, 1)), crest, 0); foam = clamp(amount * foam_tex(uv).r, 0, 1); specular_scale = clamp(1 - k foam, 0, 1)^3 "
      "(cubic, the deferred water article) or clamp(1 - k foam, 0, 1) (linear).";
  s.source = "deferred water article (listing 13: max(CoastalFoamIntensity (1 - depth / MaxDepthForCoastalFoam), wave foam) * foam texture, "
             "texture coordinates distorted by the normal; specular *= (1 - foam)^3). The source gives no values: the "
             "defaults here are ours. Its distance fade min(1, 4 / view depth) and light colour are left to the graph.";
  s.cost = "1 texture sample + ~15 ALU";
  OptionSpec tex = ports::texture("texture", "builtin:foam", "the foam texture (red channel): builtin:foam or a .png path relative to the graph");
  s.options = {tex, ports::choice("dimming", {"cubic", "linear"}, "cubic",
                                  "specular_scale = (1 - k foam)^3 (the deferred water article) or 1 - k foam, clamped to [0, 1]")};
  s.inputs = {
      ports::fixed("depth", Type::Float, "water thickness in metres (e.g. from water_depth); <= 0 is the shoreline"),
      ports::fromBuiltin("position", Type::Vec3, Builtin::WorldPosition,
                         "world point; x and z place the foam texture (default: the surface position)"),
      ports::fromBuiltin("normal", Type::Vec3, Builtin::Normal, "surface normal that distorts the texture (default: the surface normal)"),
      ports::fixed("intensity", Type::Float, Value::scalar(1.0), "coastal foam at depth 0 (the deferred water article's CoastalFoamIntensity)"),
      ports::fixed("max_depth", Type::Float, Value::scalar(1.0), "depth in metres where coastal foam ends (MaxDepthForCoastalFoam)"),
      ports::fixed("crest", Type::Float, Value::scalar(0.0), "extra foam amount, e.g. crest_foam (the deferred water article's wave foam term)"),
      ports::fixed("tex_scale", Type::Float, Value::scalar(0.1), "foam texture repeats per metre (the deferred water article's WaveValues.y)"),
      ports::fixed("distortion", Type::Float, Value::scalar(0.05), "texture offset per unit of N.xz (WaterSurfaceNormalCalculationParameter.y)"),
      ports::fixed("k", Type::Float, Value::scalar(1.0), "how strongly foam dims the specular"),
  };
  s.outputs = {ports::fixed("foam", Type::Float, "foam amount in [0, 1]"),
               ports::fixed("specular_scale", Type::Float, "factor for the specular highlight, in [0, 1]")};
  s.bypass = {{"foam", "", Value::scalar(0)}, {"specular_scale", "", Value::scalar(1)}};
  s.isSource = true;  // samples a texture
  s.parseOptions = optionParser(parseCoastalFoamOptions);
  s.emit = [](EmitContext& ctx) {
    bool cubic = ctx.options<CoastalFoamOptions>().cubic;
    GlslExpr uv = EmitContext::call("wg_coastal_foam_uv", {ctx.input("position"), ctx.input("normal"), ctx.input("tex_scale"),
                                                              ctx.input("distortion")});
    GlslExpr amount = EmitContext::call("wg_coastal_foam_amount", {ctx.input("depth"), ctx.input("max_depth"),
                                                                      ctx.input("intensity"), ctx.input("crest")});
    GlslExpr foam = ctx.temporary(Type::Float, "clamp(" + amount + " * " + ctx.sampleTexture("texture", uv) + ".r, 0.0, 1.0)");
    ctx.output(0, foam);
    ctx.output(1, EmitContext::call(cubic ? "wg_coastal_foam_specular_cubic" : "wg_coastal_foam_specular_linear",
                                    {foam, ctx.input("k")}));
  };
  s.eval = [](EvalContext& ctx) {
    const Value& pos = ctx.input("position");
    const Value& n = ctx.input("normal");
    double k = ctx.scalar("tex_scale"), dist = ctx.scalar("distortion");
    double u = k * pos[0] + 0.5 + dist * n[0], v = 0.5 - k * pos[2] + dist * n[2];
    double amount = coastalFoamAmount(ctx.scalar("depth"), ctx.scalar("max_depth"), ctx.scalar("intensity"), ctx.scalar("crest"));
    double foam = glsl::saturate(amount * ctx.sampleTexture("texture", u, v)[0]);
    ctx.output(0, Value::scalar(foam));
    ctx.output(1, Value::scalar(coastalFoamSpecular(foam, ctx.scalar("k"), ctx.options<CoastalFoamOptions>().cubic)));
  };
  // One bilinear texture sample: ~1/512 from the GPU's 8-bit filter weights.
  s.tolerance = 4e-3;
  s.hardCases = {
      {"sky depth", {{"depth", Value::scalar(3e38)}}, {}, "no coastal foam", 0, 0},
      {"negative thickness", {{"depth", Value::scalar(-2)}}, {}, "the shoreline: in [0, 1]", 0, 1},
      {"zero max depth", {{"depth", Value::scalar(0.5)}, {"max_depth", Value::scalar(0)}}, {}, "no division by zero", 0, 1},
      {"huge crest and k", {{"depth", Value::scalar(0)}, {"crest", Value::scalar(1e30)}, {"k", Value::scalar(1e30)}}, {},
       "foam clamped to [0, 1]; specular_scale in [0, 1]", 0, 1},
      {"specular scale, negative k", {{"depth", Value::scalar(0)}, {"k", Value::scalar(-5)}}, {{"dimming", "linear"}},
       "clamped to [0, 1]", 0, 1, "specular_scale"},
      {"zero intensity, infinite-ish depth", {{"depth", Value::scalar(3e38)}, {"intensity", Value::scalar(0)}}, {}, "0, not NaN", 0, 0},
  };
  return s;
}

}  // namespace wg::nodes
