// voronoi_caustics: the stylized water shader's caustics, two animated Voronoi layers at different scales
// and speeds, each (1 - F1)^3 with F1 clamped to [0, 1], averaged (or min / product).
#include <algorithm>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/foam_caustics_reference.h"
#include "nodes/node_library.h"
#include "nodes/noise_reference.h"
#include "nodes/port_builders.h"
#include "nodes/rounded_intermediates.h"
#include "nodes/voronoi_common.h"

namespace wg::nodes {
namespace {

// The stylized water shader: the second layer samples p * 1.3 + 5 and runs at 1.2 times the speed.
constexpr double kLayer2Scale = 1.3, kLayer2Offset = 5.0, kLayer2Speed = 1.2;

double layerReference(double x, double y, double jitter, double phase, bool animated, bool full) {
  return voronoiCausticsIntensity(noise::voronoi(x, y, jitter, phase, animated, full).f1);
}

enum class CausticsCombine { Average, Min, Multiply };

struct VoronoiCausticsOptions {
  VoronoiOptions voronoi;
  bool twoLayers;
  CausticsCombine combine;
  // The second layer's coordinate scale as the reference uses it: kLayer2Scale, moved only
  // by the error bound (voronoiCausticsRoundedIntermediates); the GLSL writes the literal.
  double layer2Scale = kLayer2Scale;
};
VoronoiCausticsOptions parseVoronoiCausticsOptions(const OptionReader& o) {
  return {parseVoronoiOptions(o), o.is("layers", "2"),
          o.choice<CausticsCombine>("combine", {{"average", CausticsCombine::Average},
                                                {"min", CausticsCombine::Min},
                                                {"multiply", CausticsCombine::Multiply}})};
}

}  // namespace

// The second layer samples 1.3 q + 5, rounded in float32 on its own (the product, the sum,
// 1.3 itself: about 3.2 roundings of |q|), independently of the first layer's q. Moving
// p moves both layers together, and their slopes can cancel in the average while their
// rounding errors add, so the second layer's coordinate is moved on its own.
std::vector<std::shared_ptr<const ParsedOptions>> voronoiCausticsRoundedIntermediates(const ParsedOptions& options,
                                                                                       double relative) {
  VoronoiCausticsOptions moved = options.as<VoronoiCausticsOptions>();
  if (!moved.twoLayers) return {};
  moved.layer2Scale *= 1.0 + relative;
  return {std::make_shared<const OptionsOf<VoronoiCausticsOptions>>(moved)};
}

// (1 - clamp(d, 0, 1))^3: one caustic layer's intensity for a Voronoi F1 of d.
double voronoiCausticsIntensity(double d) {
  double m = 1.0 - glsl::saturate(d);
  return m * m * m;
}

NodeSpec voronoiCausticsNode() {
  NodeSpec s;
  s.type = "voronoi_caustics";
  s.family = "caustics";
  s.summary = "Animated caustic light pattern from one or two Voronoi layers (the stylized water shader).";
  s.formula =
      "q = p * scale; c1 = (1 - clamp(F1(q, phase), 0, 1))^3, c2 = (1 - clamp(F1(1.3 q + 5, phase2), 0, 1))^3 with "
      "phase = mod(speed t, 2 pi), phase2 = mod(1.2 speed t, 2 pi) (F1 from the voronoi node: jitter, search). "
      "combine: average (c1 + c2) / 2 (the stylized water shader), min(c1, c2), or multiply c1 c2; layers = 1 gives c1. "
      "caustics = intensity * combined. F1 can exceed 1, hence the clamp before 1 - F1.";
  s.source = "stylized water shader (section 6: voronoi(uv, t) and voronoi(uv * 1.3 + 5, 1.2 t), pow(1 - d, 3), averaged)";
  s.cost = "per layer one voronoi (3x3: 9 hashes ~250 ALU + 18 sin/cos animated; 2x2: 4 hashes ~110 ALU + 8 sin/cos); "
           "layers 2 doubles it";
  s.inputs = {ports::fromBuiltin("p", Type::Vec2, Builtin::Uv, "2D coordinate (default: the mesh uv), e.g. world xz"),
              ports::fixed("scale", Type::Float, Value::scalar(4.0), "Voronoi cells per unit of p"),
              ports::fixed("jitter", Type::Float, Value::scalar(1.0), "feature point jitter, 0..1"),
              ports::fixed("time", Type::Float, Value::scalar(0.0), "seconds, used when animation = time_input"),
              ports::fixed("intensity", Type::Float, Value::scalar(1.0), "brightness multiplier")};
  s.outputs = {ports::fixed("caustics", Type::Float, "caustic intensity, in [0, intensity]")};
  s.bypass = {{"caustics", "", Value::scalar(0)}};
  s.options = voronoiOptions(1.0);
  s.options.push_back(ports::knob(
      ports::choice("layers", {"2", "1"}, "2", "two layers (the stylized water shader) or one (half the cost)"), {"1", "2"}));
  s.options.push_back(ports::choice("combine", {"average", "min", "multiply"}, "average",
                                    "how two layers combine: average (the stylized water shader), min (thinner lines), multiply (sparser)"));
  s.parseOptions = optionParser(parseVoronoiCausticsOptions);
  s.isSource = true;  // reads the time phase
  s.emit = [](EmitContext& ctx) {
    const VoronoiCausticsOptions& o = ctx.options<VoronoiCausticsOptions>();
    bool full = o.voronoi.fullSearch, animated = o.voronoi.animated();
    std::string a = animated ? "true" : "false", f = full ? "true" : "false";
    GlslExpr p = ctx.input("p");  // one call per statement: a stable emission order
    GlslExpr k = ctx.input("scale");
    GlslExpr q = ctx.temporary(Type::Vec2, "(" + p + " * " + k + ")");
    GlslExpr c1 = ctx.temporary(
        Type::Float, EmitContext::call("wg_voronoi_caustics_layer", {q, ctx.input("jitter"), emitVoronoiPhase(ctx, o.voronoi, 1.0), a, f}));
    GlslExpr c = c1;
    if (o.twoLayers) {
      GlslExpr q2 = "(" + q + " * " + ctx.literal(kLayer2Scale) + " + " + ctx.literal(kLayer2Offset) + ")";
      GlslExpr c2 = ctx.temporary(
          Type::Float,
          EmitContext::call("wg_voronoi_caustics_layer", {q2, ctx.input("jitter"), emitVoronoiPhase(ctx, o.voronoi, kLayer2Speed), a, f}));
      c = o.combine == CausticsCombine::Average ? "(0.5 * (" + c1 + " + " + c2 + "))"
          : o.combine == CausticsCombine::Min   ? "min(" + c1 + ", " + c2 + ")"
                            : "(" + c1 + " * " + c2 + ")";
    }
    GlslExpr intensity = ctx.input("intensity");
    ctx.output(0, "(" + intensity + " * " + c + ")");
  };
  s.eval = [](EvalContext& ctx) {
    const VoronoiCausticsOptions& o = ctx.options<VoronoiCausticsOptions>();
    bool full = o.voronoi.fullSearch, animated = o.voronoi.animated();
    const Value& p = ctx.input("p");
    double k = ctx.scalar("scale"), jitter = ctx.scalar("jitter");
    double qx = p[0] * k, qy = p[1] * k;
    double c = layerReference(qx, qy, jitter, evalVoronoiPhase(ctx, o.voronoi, 1.0), animated, full);
    if (o.twoLayers) {
      double c2 = layerReference(qx * o.layer2Scale + kLayer2Offset, qy * o.layer2Scale + kLayer2Offset, jitter,
                                 evalVoronoiPhase(ctx, o.voronoi, kLayer2Speed), animated, full);
      c = o.combine == CausticsCombine::Average ? 0.5 * (c + c2) : o.combine == CausticsCombine::Min ? std::min(c, c2) : c * c2;
    }
    ctx.output(0, Value::scalar(ctx.scalar("intensity") * c));
  };
  // F1's float32 evaluation error times the cube's slope (3). F1 from float32 q: each
  // feature point is 0.5 + jitter/2 (sin, cos)(phase + 2 pi h), whose argument (< 4 pi)
  // rounds by 7.5e-7 and 2 pi h by 3.7e-7: 5.6e-7 per coordinate after the 1/2, plus 2
  // roundings of the cell offset sum (<= 2): 8e-7 per coordinate, 1.2e-6 along the
  // distance, 1.4e-6 with the dot product and sqrt. Per layer 3 * 1.4e-6 = 4.2e-6; the
  // second layer's coordinate 1.3 q + 5 rounds by (0.03 |q| + 5) 2^-24 more (the |q| part
  // is conditioning, the second layer's counted on its own: see
  // voronoiCausticsRoundedIntermediates). Averaged, min or multiplied: <= 7.2e-6. Measured
  // on llvmpipe: F1 to 2.5e-7 over 10,000 points, one layer's caustics to 5.2e-7.
  s.tolerance = 1e-5;
  s.conditionRoundings = 4;
  s.conditionWhy = "grows with the cell coordinates (the second layer's 1.3 q + 5 counted on its own) and float32 time "
                   "inputs, and where two cells are nearly equidistant";
  s.hardCases = {
      // At q = (50.09375, 86.09375) (scale 1, jitter 1, static), both searches find
      // F1 = 1.2008 > 1: the unclamped 1 - F1 would be a negative base.
      {"F1 > 1", {{"p", Value::vector({50.09375, 86.09375})}, {"scale", Value::scalar(1.0)}},
       {{"animation", "static"}, {"layers", "1"}}, "F1 clamped: 0, not NaN", 0, 1},
      {"F1 > 1, 2x2 search", {{"p", Value::vector({50.09375, 86.09375})}, {"scale", Value::scalar(1.0)}},
       {{"animation", "static"}, {"layers", "1"}, {"search", "2x2"}}, "F1 clamped: 0, not NaN", 0, 1},
      {"huge time input 1e6 s", {{"p", Value::vector({0.3, 0.6})}, {"time", Value::scalar(1e6)}},
       {{"animation", "time_input"}, {"combine", "min"}}, "phase wrapped, in [0, 1]", 0, 1},
      {"huge coordinates 1e5 m", {{"p", Value::vector({1e5, -1e5})}}, {{"combine", "multiply"}}, "in [0, 1]", 0, 1},
  };
  return s;
}

}  // namespace wg::nodes
