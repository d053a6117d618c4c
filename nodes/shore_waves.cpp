// shore_waves: the stylized water shader's bands of foam running up the shore, sin of the shore depth
// plus time (a crest's depth falls as time grows), sharpened by squaring and fading out with depth.
#include <cmath>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/foam_caustics_reference.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"

namespace wg::nodes {

// As nodes/glsl/shore_waves.glsl; phase = mod(speed t, 2 pi).
double shoreWavesReference(double depth, double frequency, double phase, double amplitude, double distance) {
  const double tau = 6.283185307179586;
  double dmax = std::max(distance, 1e-6);
  double d = glsl::clamp(depth, 0.0, dmax);
  double w = std::sin(glsl::mod(d * frequency + phase, tau)) * 0.5 + 0.5;
  w *= w;
  return glsl::saturate(w * amplitude * (1.0 - d / dmax));
}

namespace {

struct ShoreWavesOptions {
  double speed;  // rad/s
};
ShoreWavesOptions parseShoreWavesOptions(const OptionReader& o) { return {o.number("speed")}; }

}  // namespace

NodeSpec shoreWavesNode() {
  NodeSpec s;
  s.type = "shore_waves";
  s.family = "foam";
  s.summary = "Bands of foam running towards the shore: a sine of the shore depth plus time, fading with depth (the stylized water shader).";
  s.formula =
      "d = clamp(depth, 0, D), D = max(distance, 1e-6); phase = mod(speed t, 2 pi); "
      "w = (sin(mod(d frequency + phase, 2 pi)) / 2 + 1/2)^2; waves = saturate(w amplitude (1 - d / D)). A crest lies at "
      "d frequency + speed t = pi / 2 (mod 2 pi): its depth falls as t grows, so a positive speed runs towards the waterline.";
  s.source = "stylized water shader (section 9: ShoreWave, sin(shoreDepth * frequency - time * speed) * 0.5 + 0.5, squared, times "
             "amplitude * saturate(1 - depth / distance)); the source subtracts the time term, which moves the bands out to sea "
             "for a positive speed although it describes waves breaking on the shore: the sign here makes a positive speed run "
             "ashore. The source gives no values: the defaults here are ours";
  s.cost = "1 sin + ~12 ALU; the phase is a time-phase uniform";
  s.inputs = {
      ports::fixed("depth", Type::Float, "shore depth in metres (e.g. water_depth); <= 0 is the waterline"),
      ports::fixed("frequency", Type::Float, Value::scalar(6.0), "radians per metre of depth: band spacing 2 pi / frequency"),
      ports::fixed("amplitude", Type::Float, Value::scalar(1.0), "band strength (result clamped to [0, 1])"),
      ports::fixed("distance", Type::Float, Value::scalar(2.0), "depth in metres where the bands have faded out"),
  };
  s.outputs = {ports::fixed("waves", Type::Float, "wave foam mask in [0, 1]")};
  s.options = {ports::number("speed", 2.0, -100.0, 100.0,
                             "radians per second the bands advance (compile-time: a double-precision time phase, exact "
                             "at t = 1e6 s); positive runs towards the shore")};
  s.isSource = true;  // reads a time phase
  s.parseOptions = optionParser(parseShoreWavesOptions);
  s.emit = [](EmitContext& ctx) {
    double speed = ctx.options<ShoreWavesOptions>().speed;
    GlslExpr phase = speed == 0.0 ? "0.0" : ctx.timePhase(speed);
    ctx.output(0, EmitContext::call("wg_shore_waves", {ctx.input("depth"), ctx.input("frequency"), phase,
                                                       ctx.input("amplitude"), ctx.input("distance")}));
  };
  s.eval = [](EvalContext& ctx) {
    double speed = ctx.options<ShoreWavesOptions>().speed;
    double phase = speed == 0.0 ? 0.0 : glsl::mod(speed * ctx.environment().time[0], 6.283185307179586);
    ctx.output(0, Value::scalar(shoreWavesReference(ctx.scalar("depth"), ctx.scalar("frequency"), phase,
                                                    ctx.scalar("amplitude"), ctx.scalar("distance"))));
  };
  s.tolerance = 1e-5;
  s.conditionRoundings = 4;
  s.conditionWhy = "grows with the phase frequency x depth: at 1e4 and more float32 keeps few of its digits";
  s.hardCases = {
      {"sky depth", {{"depth", Value::scalar(3e38)}}, {}, "clamped: 0, not sin(inf)", 0, 0},
      {"negative thickness", {{"depth", Value::scalar(-1)}}, {}, "the waterline: in [0, 1]", 0, 1},
      {"zero distance", {{"depth", Value::scalar(0.5)}, {"distance", Value::scalar(0)}}, {}, "no division by zero: 0", 0, 0},
      {"huge frequency", {{"depth", Value::scalar(1)}, {"frequency", Value::scalar(1e30)}}, {},
       "finite, in [0, 1] (a phase of 1e30 rad has no digits in float32 or double: only the range is checked)", 0, 1,
       "", 1.0},
      {"huge amplitude", {{"depth", Value::scalar(0.3)}, {"amplitude", Value::scalar(1e30)}}, {}, "clamped to [0, 1]", 0, 1},
  };
  return s;
}

}  // namespace wg::nodes
