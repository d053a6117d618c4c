// voronoi: cellular noise with one PCG-hashed feature point per cell: F1, F2 and the
// nearest cell, static or with points orbiting their cell centres over time (the stylized water shader's
// animated Voronoi, made exact at any time by a double-precision phase).
#include <cmath>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/node_library.h"
#include "nodes/noise_reference.h"
#include "nodes/port_builders.h"
#include "nodes/voronoi_common.h"

namespace wg::nodes {

GlslExpr emitVoronoiPhase(EmitContext& ctx, const VoronoiOptions& o, double speedScale) {
  double speed = o.speed * speedScale;
  if (o.animation == VoronoiAnimation::Static) return "0.0";
  if (o.animation == VoronoiAnimation::Time) return speed == 0.0 ? "0.0" : ctx.timePhase(speed);
  // A time input: wrap speed * time before it reaches sin (float time is coarse at 1e6 s).
  GlslExpr t = ctx.input("time");
  return "mod(" + ctx.literal(speed) + " * " + t + ", " + ctx.literal(noise::kTau) + ")";
}

double evalVoronoiPhase(EvalContext& ctx, const VoronoiOptions& o, double speedScale) {
  double speed = o.speed * speedScale;
  if (o.animation == VoronoiAnimation::Static) return 0.0;
  double t = o.animation == VoronoiAnimation::Time ? ctx.environment().time[0] : ctx.scalar("time");
  return glsl::mod(speed * t, noise::kTau);
}

std::vector<OptionSpec> voronoiOptions(double defaultSpeed) {
  return {
      ports::knob(ports::choice("search", {"3x3", "2x2"}, "3x3",
                                "3x3 cells (9 hashes; at jitter 1, F1 differs from a 5x5 search at ~2 points in 10^6 with static "
                                "points, ~40 in 10^6 with orbiting ones, by up to 0.14) or the 2x2 block on the point's "
                                "side of its cell (4 hashes; at jitter 1, F1 too large at ~0.9% of points static, ~2.9% "
                                "orbiting, by up to 0.55; F2 often too large)"),
                  {"2x2", "3x3"}),
      ports::choice("animation", {"static", "time", "time_input"}, "time",
                    "static points; points orbiting with the scene time (a double-precision phase uniform, exact at "
                    "t = 1e6 s); or orbiting with the `time` input (wrapped with mod before sin)"),
      ports::number("speed", defaultSpeed, -100.0, 100.0, "orbit angular speed in radians per second"),
  };
}

VoronoiOptions parseVoronoiOptions(const OptionReader& o) {
  return {o.is("search", "3x3"),
          o.choice<VoronoiAnimation>("animation", {{"static", VoronoiAnimation::Static},
                                                   {"time", VoronoiAnimation::Time},
                                                   {"time_input", VoronoiAnimation::TimeInput}}),
          o.number("speed")};
}

NodeSpec voronoiNode() {
  NodeSpec s;
  s.type = "voronoi";
  s.family = "noise";
  s.summary = "Voronoi (cellular) noise: distances to the nearest and second-nearest feature points, and the nearest cell.";
  s.formula =
      "q = p * scale; one point per integer cell c at c + 0.5 + j w, j = clamp(jitter, 0, 1), h = hash(c).xy; "
      "static: w = h - 0.5; animated: w = 0.5 (sin(phase + 2 pi h.x), cos(phase + 2 pi h.y)), phase = mod(speed t, 2 pi). "
      "F1 = min |point - q|, F2 = the second smallest, over the 3x3 cells around q (or the 2x2 block on q's side). "
      "cell = the integer cell of the nearest point. F1 is not bounded by 1 (up to ~1.4, more with 2x2).";
  s.source = "stylized water shader (section 6: the animated Voronoi behind the caustics; fract(sin) hash replaced by PCG)";
  s.cost = "3x3: 9 hashes + 9 distances (~250 ALU), +18 sin/cos when animated; 2x2: 4 hashes (~110 ALU), +8 sin/cos";
  s.inputs = {ports::fromBuiltin("p", Type::Vec2, Builtin::Uv, "2D coordinate (default: the mesh uv)"),
              ports::fixed("scale", Type::Float, Value::scalar(1.0), "cells per unit of p"),
              ports::fixed("jitter", Type::Float, Value::scalar(1.0), "how far points stray from cell centres, 0..1"),
              ports::fixed("time", Type::Float, Value::scalar(0.0), "seconds, used when animation = time_input")};
  s.outputs = {ports::fixed("f1", Type::Float, "distance to the nearest point, >= 0"),
               ports::fixed("f2", Type::Float, "distance to the second-nearest point, >= f1"),
               ports::fixed("cell", Type::Vec2, "integer cell of the nearest point (a per-cell id)")};
  s.options = voronoiOptions(1.0);
  s.parseOptions = optionParser(parseVoronoiOptions);
  s.isSource = true;  // reads the time phase
  s.emit = [](EmitContext& ctx) {
    const VoronoiOptions& o = ctx.options<VoronoiOptions>();
    bool full = o.fullSearch, animated = o.animated();
    GlslExpr p = ctx.input("p");  // one call per statement: a stable emission order
    GlslExpr k = ctx.input("scale");
    GlslExpr q = "(" + p + " * " + k + ")";
    GlslExpr v = ctx.temporary(Type::Vec4, EmitContext::call("wg_voronoi", {q, ctx.input("jitter"), emitVoronoiPhase(ctx, o, 1.0),
                                                                               animated ? "true" : "false", full ? "true" : "false"}));
    ctx.output(0, v + ".x");
    ctx.output(1, v + ".y");
    ctx.output(2, v + ".zw");
  };
  s.eval = [](EvalContext& ctx) {
    const VoronoiOptions& o = ctx.options<VoronoiOptions>();
    bool full = o.fullSearch, animated = o.animated();
    const Value& p = ctx.input("p");
    double k = ctx.scalar("scale");
    auto r = noise::voronoi(p[0] * k, p[1] * k, ctx.scalar("jitter"), evalVoronoiPhase(ctx, o, 1.0), animated, full);
    ctx.output(0, Value::scalar(r.f1));
    ctx.output(1, Value::scalar(r.f2));
    ctx.output(2, Value::vector({r.cellX, r.cellY}));
  };
  // Distances in float32 relative to the cell; a near-tie between two points can still pick
  // a different nearest cell on the GPU (F1 and F2 stay continuous there).
  s.tolerance = 1e-4;
  s.conditionRoundings = 4;
  s.conditionWhy = "grows with the cell coordinates and float32 time inputs, and where two cells are nearly equidistant (the nearest cell changes)";
  s.hardCases = {
      {"huge coordinates 1e5 m", {{"p", Value::vector({1e5, -1e5})}}, {}, "finite, F1 <= ~1.42", 0, 1.5},
      {"jitter out of range", {{"p", Value::vector({0.3, 0.7})}, {"jitter", Value::scalar(7)}}, {}, "clamped to 1", 0, 1.5},
      {"huge time input 1e6 s", {{"p", Value::vector({2.3, 4.1})}, {"time", Value::scalar(1e6)}},
       {{"animation", "time_input"}}, "phase wrapped, finite", 0, 1.5},
      {"2x2 search", {{"p", Value::vector({0.1, 0.1})}}, {{"search", "2x2"}},
       "finite, F1 <= sqrt 2 (the point's own cell is always searched)", 0, 1.5},
  };
  return s;
}

}  // namespace wg::nodes
