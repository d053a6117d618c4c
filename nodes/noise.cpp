// Noise family, part 1: `hash` (PCG3D on the integer cell, bit-identical on CPU and GPU),
// `value_noise` (hashed lattice, cubic Hermite blend, the top-down water plan) and `fbm` (octaves of value
// noise). `voronoi` is in voronoi.cpp. The double references live in noise_reference.cpp.
#include <string>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/node_library.h"
#include "nodes/noise_reference.h"
#include "nodes/port_builders.h"

namespace wg::nodes {
namespace {

// p must be a vec2 or a vec3 (the hashed cell's dimension).
void requireVec2OrVec3(InferContext& ctx, int port) {
  Type t = ctx.inputTypes[static_cast<size_t>(port)];
  if (t != Type::Vec2 && t != Type::Vec3) {
    ctx.error = "input '" + ctx.spec.inputs[static_cast<size_t>(port)].name + "' takes vec2 or vec3, not " +
                std::string(typeName(t));
    ctx.errorInput = port;
  }
}

std::string suffix(Type t) { return t == Type::Vec2 ? "_vec2" : "_vec3"; }

// The coordinate times the scale input, as GLSL and in double.
GlslExpr scaled(EmitContext& ctx) {
  GlslExpr p = ctx.input("p");  // one call per statement: a stable emission order
  GlslExpr k = ctx.input("scale");
  return "(" + p + " * " + k + ")";
}
Value scaled(EvalContext& ctx) { return glsl::scale(ctx.input("p"), ctx.scalar("scale")); }

PortSpec positionPort(std::string doc) {
  PortSpec p = ports::custom("p", std::move(doc));
  p.defaultBuiltin = Builtin::WorldPosition;
  return p;
}

OptionSpec octavesOption() {
  return ports::knob(ports::integer("octaves", 4, 1, 8, "number of value-noise layers (each octave costs one value_noise)"),
                    {1, 2, 3, 4, 5, 6, 7, 8});
}

struct FbmOptions {
  int octaves;
};
FbmOptions parseFbmOptions(const OptionReader& o) { return {o.integer("octaves")}; }

}  // namespace

NodeSpec hashNode() {
  NodeSpec s;
  s.type = "hash";
  s.family = "noise";
  s.summary = "Integer hash of a coordinate's cell: three pseudo-random numbers in [0, 1), bit-identical on CPU and GPU.";
  s.formula =
      "c = uint(int(clamp(floor(p), -2^31, 2147483520))) per component (a vec2 cell is (x, y, 0)); "
      "h = PCG3D(c): v = v * 1664525 + 1013904223; v.x += v.y v.z; v.y += v.z v.x; v.z += v.x v.y; v ^= v >> 16; "
      "the three mixing steps again (all mod 2^32). vec = (h >> 8) * 2^-24 per component, value = vec.x.";
  s.source = "top-down water plan (its noise hash, replaced by an integer hash: Jarzynski and Olano, \"Hash Functions for GPU Rendering\", 2020)";
  s.cost = "~20 integer ALU (PCG3D), no transcendental functions";
  s.inputs = {positionPort("vec2 or vec3 coordinate (default: the world position); its integer cell floor(p) is hashed")};
  s.outputs = {ports::fixed("value", Type::Float, "one hashed number in [0, 1) (= vec.x)"),
               ports::fixed("vec", Type::Vec3, "three independent hashed numbers in [0, 1)")};
  s.infer = [](InferContext& ctx) { requireVec2OrVec3(ctx, 0); };
  s.emit = [](EmitContext& ctx) {
    GlslExpr h = ctx.temporary(Type::Vec3, EmitContext::call("wg_hash" + suffix(ctx.inputType(0)), {ctx.input("p")}));
    ctx.output(0, h + ".x");
    ctx.output(1, h);
  };
  s.eval = [](EvalContext& ctx) {
    const Value& p = ctx.input("p");
    auto h = p.size() == 2 ? noise::hash2(p[0], p[1]) : noise::hash3(p[0], p[1], p[2]);
    ctx.output(0, Value::scalar(h[0]));
    ctx.output(1, Value::vector({h[0], h[1], h[2]}));
  };
  // The hash is exact: the GPU's words equal the CPU's for any float32 input.
  s.tolerance = 1e-12;
  s.hardCases = {
      {"cell 1e7", {{"p", Value::vector({1e7, 1e7 + 1, -1e7})}}, {}, "in [0, 1), exact on the GPU", 0, 1},
      {"negative cells", {{"p", Value::vector({-0.5, -1.0, -3.25})}}, {}, "in [0, 1)", 0, 1},
      {"beyond the int range", {{"p", Value::vector({1e30, -1e30, 3e38})}}, {}, "clamped cell, in [0, 1)", 0, 1},
      {"huge coordinates 1e5 m (vec2)", {{"p", Value::vector({1e5, -1e5})}}, {}, "in [0, 1)", 0, 1},
  };
  return s;
}

NodeSpec valueNoiseNode() {
  NodeSpec s;
  s.type = "value_noise";
  s.family = "noise";
  s.summary = "Value noise: PCG-hashed values on the integer lattice, blended smoothly (2D or 3D).";
  s.formula =
      "q = p * scale; i = floor(q), f = q - i, u = f^2 (3 - 2f); lattice(c) = hash(c).x; "
      "2D: mix(mix(l(i), l(i+x), u.x), mix(l(i+y), l(i+x+y), u.x), u.y); 3D: the same trilinearly over 8 corners. "
      "Output in [0, 1).";
  s.source = "top-down water plan (valueNoise: cubic Hermite blend of four hashed corners)";
  s.cost = "2D: 4 hashes (~80 integer ALU) + ~15 ALU; 3D: 8 hashes + ~30 ALU";
  s.inputs = {positionPort("vec2 or vec3 coordinate (default: the world position)"),
              ports::fixed("scale", Type::Float, Value::scalar(1.0), "lattice cells per unit of p")};
  s.outputs = {ports::fixed("value", Type::Float, "noise in [0, 1)")};
  s.infer = [](InferContext& ctx) { requireVec2OrVec3(ctx, 0); };
  s.emit = [](EmitContext& ctx) {
    ctx.output(0, EmitContext::call("wg_value_noise" + suffix(ctx.inputType(0)), {scaled(ctx)}));
  };
  s.eval = [](EvalContext& ctx) {
    Value q = scaled(ctx);
    ctx.output(0, Value::scalar(q.size() == 2 ? noise::valueNoise2(q[0], q[1]) : noise::valueNoise3(q[0], q[1], q[2])));
  };
  // The evaluation, from float32 q: floor and q - floor(q) are exact; u = f^2 (3 - 2f)
  // rounds about 5 times (|error| <= 5 * 2^-24, u <= 1); each mix a + u (b - a) adds its
  // own 3 roundings to |b - a| times u's error, and 2D nests two levels, 3D three:
  // <= 3 * (5 + 3) * 2^-24 = 1.43e-6. The lattice values are exact (24-bit hashes).
  s.tolerance = 2e-6;
  // q = p * scale rounds once in float32 (the reference multiplies in double): at |q| =
  // 1e3 that moves q by 6e-5 and the noise by up to 1.5 times as much.
  s.conditionRoundings = 1;
  s.conditionWhy = "grows with the coordinate q = p scale, whose float32 product rounds (|q| 2^-24 times the Hermite slope 1.5)";
  s.hardCases = {
      {"huge coordinates 1e5 m", {{"p", Value::vector({1e5, 3.5, -1e5})}}, {}, "in [0, 1)", 0, 1},
      {"beyond the int range", {{"p", Value::vector({1e30, -1e30})}}, {}, "clamped cell, in [0, 1)", 0, 1},
      {"negative cells", {{"p", Value::vector({-0.25, -7.75})}}, {}, "in [0, 1)", 0, 1},
  };
  return s;
}

NodeSpec fbmNode() {
  NodeSpec s;
  s.type = "fbm";
  s.family = "noise";
  s.summary = "Fractal Brownian motion: octaves of value noise at growing frequency and shrinking amplitude.";
  s.formula =
      "lac = clamp(lacunarity, 0, 8), g = clamp(gain, 0, 4); q_0 = p * scale, q_(i+1) = q_i * lac, a_i = g^i; "
      "fbm = sum_i a_i value_noise(q_i + i (17.31, 9.73[, 5.47])) / sum_i a_i, i < octaves. Output in [0, 1).";
  s.source = "top-down water plan (layered value noise for the foam mask and colour variation)";
  s.cost = "octaves x value_noise: 2D ~100 ALU per octave (4 hashes), 3D ~190 (8 hashes); octaves 1..8";
  s.inputs = {positionPort("vec2 or vec3 coordinate (default: the world position)"),
              ports::fixed("scale", Type::Float, Value::scalar(1.0), "lattice cells per unit of p (first octave)"),
              ports::fixed("lacunarity", Type::Float, Value::scalar(2.0), "frequency ratio between octaves, clamped to [0, 8]"),
              ports::fixed("gain", Type::Float, Value::scalar(0.5), "amplitude ratio between octaves, clamped to [0, 4]")};
  s.outputs = {ports::fixed("value", Type::Float, "noise in [0, 1)")};
  s.parseOptions = optionParser(parseFbmOptions);
  s.options = {octavesOption()};
  s.infer = [](InferContext& ctx) { requireVec2OrVec3(ctx, 0); };
  s.emit = [](EmitContext& ctx) {
    int octaves = ctx.options<FbmOptions>().octaves;
    ctx.output(0, EmitContext::call("wg_fbm" + suffix(ctx.inputType(0)),
                                    {scaled(ctx), std::to_string(octaves), ctx.input("lacunarity"), ctx.input("gain")}));
  };
  s.eval = [](EvalContext& ctx) {
    Value q = scaled(ctx);
    int octaves = ctx.options<FbmOptions>().octaves;
    double lac = ctx.scalar("lacunarity"), gain = ctx.scalar("gain");
    ctx.output(0, Value::scalar(q.size() == 2 ? noise::fbm2(q[0], q[1], octaves, lac, gain)
                                              : noise::fbm3(q[0], q[1], q[2], octaves, lac, gain)));
  };
  // The evaluation: octave i samples value noise (its own bound, 2e-6) at q_i + i c,
  // c = (17.31, 9.73[, 5.47]). The GPU's coordinate is off by up to (3 i |c| + |q_i|) 2^-24:
  // c rounded to float32, the product i c and the sum each round. The |q_i| part grows with
  // p and is the conditioning below (p lacunarity^i rounds as p does); the constant part,
  // at most 3 * 7 * (17.31 + 9.73 + 5.47) 2^-24 = 4.1e-5 summed over the axes, times the
  // Hermite slope 1.5, with every weight on the last octave (gain 4): 6.1e-5, plus the
  // noise's 2e-6 and the weighted sum's few roundings. Measured on llvmpipe: 1.5e-6 for
  // |p scale| < 60 with 4 octaves.
  s.tolerance = 1e-4;
  s.conditionRoundings = 4;
  s.conditionWhy = "grows with the octave coordinates p lacunarity^i (large coordinates, gain or lacunarity) and at cell edges";
  s.hardCases = {
      {"8 octaves at 1e5 m", {{"p", Value::vector({1e5, -1e5})}}, {{"octaves", 8}}, "in [0, 1)", 0, 1},
      {"zero gain", {{"p", Value::vector({0.3, 0.7, 0.1})}, {"gain", Value::scalar(0)}}, {}, "the first octave only", 0, 1},
      {"huge gain and lacunarity", {{"p", Value::vector({0.3, 0.7})}, {"gain", Value::scalar(1e30)},
                                    {"lacunarity", Value::scalar(1e30)}}, {{"octaves", 8}}, "clamped, in [0, 1)", 0, 1},
      {"negative gain", {{"p", Value::vector({0.3, 0.7})}, {"gain", Value::scalar(-2)}}, {}, "clamped to 0, in [0, 1)", 0, 1},
  };
  return s;
}

}  // namespace wg::nodes
