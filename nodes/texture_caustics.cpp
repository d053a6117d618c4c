// texture_caustics: the deferred water article's caustics, two samples of a height texture scrolling in
// opposite directions, c = clamp(1 - |a + b - 1|, 0, 1)^9.
#include <cmath>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/foam_caustics_reference.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"

namespace wg::nodes {

// clamp(1 - |a + b - 1|, 0, 1)^9 as two cubes (wg_texture_caustics_shape).
double textureCausticsShape(double a, double b) {
  double c = glsl::saturate(1.0 - std::fabs(a + b - 1.0));
  c *= c * c;
  c *= c * c;
  return c;
}

NodeSpec textureCausticsNode() {
  NodeSpec s;
  s.type = "texture_caustics";
  s.family = "caustics";
  s.summary = "Caustics from two oppositely scrolling samples of a height texture (the deferred water article).";
  s.formula =
      "uv = (scale x + 0.5, 0.5 - scale z) of the world point; m = mod(time * velocity, 1); "
      "a = tex(uv + m).r, b = tex(1.5 uv - m).r; caustics = intensity * clamp(1 - |a + b - 1|, 0, 1)^9.";
  s.source = "deferred water article (listing 14: WaterHeightTexture sampled at uv + move and 1.5 uv - move, 1 - |a + b - 1|, ^9)";
  s.cost = "2 texture samples + ~12 ALU";
  OptionSpec tex = ports::texture("texture", "builtin:height", "the height texture sampled (red channel): builtin:height or a .png path relative to the graph");
  s.options = {tex};
  s.inputs = {
      ports::fromBuiltin("position", Type::Vec3, Builtin::WorldPosition,
                         "world point the caustics fall on (x and z are used; default: the surface position)"),
      ports::fixed("scale", Type::Float, Value::scalar(0.1), "texture repeats per metre (the deferred water article's CausticsValues.x)"),
      ports::fixed("velocity", Type::Vec2, Value::vector({0.02, 0.01}),
                   "scroll speed in texture units per second (the deferred water article's CausticsValues.w times the wind direction)"),
      ports::fromBuiltin("time", Type::Float, Builtin::Time, "seconds (default: the scene time)"),
      ports::fixed("intensity", Type::Float, Value::scalar(1.0), "brightness (the deferred water article's CausticsValues.y)"),
  };
  s.outputs = {ports::fixed("caustics", Type::Float, "caustic intensity, in [0, intensity]")};
  s.bypass = {{"caustics", "", Value::scalar(0)}};
  s.isSource = true;  // samples a texture
  s.emit = [](EmitContext& ctx) {
    GlslExpr uv = ctx.temporary(Type::Vec2, EmitContext::call("wg_texture_caustics_uv", {ctx.input("position"), ctx.input("scale")}));
    // The texture repeats every 1 in uv, so the scroll wraps there exactly.
    GlslExpr time = ctx.input("time");  // one call per statement: a stable emission order
    GlslExpr velocity = ctx.input("velocity");
    GlslExpr m = ctx.temporary(Type::Vec2, "mod(" + time + " * " + velocity + ", 1.0)");
    GlslExpr a = ctx.temporary(Type::Float, ctx.sampleTexture("texture", uv + " + " + m) + ".r");
    GlslExpr b = ctx.temporary(Type::Float, ctx.sampleTexture("texture", "1.5 * " + uv + " - " + m) + ".r");
    GlslExpr intensity = ctx.input("intensity");
    ctx.output(0, "(" + intensity + " * " + EmitContext::call("wg_texture_caustics_shape", {a, b}) + ")");
  };
  s.eval = [](EvalContext& ctx) {
    const Value& pos = ctx.input("position");
    const Value& vel = ctx.input("velocity");
    double k = ctx.scalar("scale"), t = ctx.scalar("time");
    double u = k * pos[0] + 0.5, v = 0.5 - k * pos[2];
    double mu = glsl::mod(t * vel[0], 1.0), mv = glsl::mod(t * vel[1], 1.0);
    double a = ctx.sampleTexture("texture", u + mu, v + mv)[0];
    double b = ctx.sampleTexture("texture", 1.5 * u - mu, 1.5 * v - mv)[0];
    ctx.output(0, Value::scalar(ctx.scalar("intensity") * textureCausticsShape(a, b)));
  };
  // GPU bilinear weights have 8 fractional bits: ~1/512 per sample, times the ninth
  // power's slope (<= 9).
  s.tolerance = 2e-2;
  s.hardCases = {
      {"huge time 1e6 s", {{"time", Value::scalar(1e6)}}, {}, "scroll wrapped, in [0, 1]", 0, 1},
      {"huge coordinates 1e5 m", {{"position", Value::vector({1e5, 0, -1e5})}}, {}, "in [0, 1]", 0, 1},
      {"negative time and velocity", {{"time", Value::scalar(-524288)}, {"velocity", Value::vector({-0.3, 0.7})}}, {},
       "mod floors: in [0, 1]", 0, 1},
  };
  return s;
}

}  // namespace wg::nodes
