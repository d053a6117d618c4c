// The geometric vocabulary: distance, reflect, refract and faceforward, on
// float/vec2/vec3/vec4 as GLSL defines them (a float splats to the widest input). GLSL
// defines each for every finite input (refract returns the zero vector under total
// internal reflection), so each emits the raw built-in. The optics nodes (reflect_dir,
// refract_dir) are the water-specific forms that normalise and pick the media; these
// are the plain built-ins for a user's own formula.
#include <algorithm>
#include <cmath>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/math_builders.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"

namespace wg::nodes {

namespace {

using glsl::dot;
using glsl::scale;
using glsl::sub;

// A Gen input splatted to the node's type (a float given where the others are vectors).
Value widened(const Value& v, Type t) { return glsl::map1(v, t, [](double x) { return x; }); }

Value up() { return Value::vector({0, 1, 0}); }

}  // namespace

NodeSpec distanceNode() {
  NodeSpec s = math::mathNode("distance", "Euclidean distance between two points (float32 overflows past 1.8e19).",
                              "out = length(a - b)");
  s.inputs = {ports::gen("a", "first point"), ports::gen("b", 0, "second point")};
  s.outputs = {ports::fixed("out", Type::Float, "the distance, >= 0")};
  s.facts = math::alwaysWithin(0, INFINITY);
  s.emit = [](EmitContext& ctx) { ctx.output(0, EmitContext::call("distance", {ctx.input(0), ctx.input(1)})); };
  s.eval = [](EvalContext& ctx) {
    Type t = floatVector(std::max(ctx.input(0).size(), ctx.input(1).size()));
    ctx.output(0, Value::scalar(glsl::length(sub(widened(ctx.input(0), t), widened(ctx.input(1), t)))));
  };
  s.cost = "a subtraction, a dot product and a sqrt";
  // a - b cancels when the points are close: rounding of a and b moves the difference by
  // 2^-24 |a| while it may itself be much smaller.
  s.conditionRoundings = 1;
  s.conditionWhy = "grows as |a| / |a - b| for points close together far from the origin (a - b cancels)";
  s.hardCases = {{"the same point", {{"a", Value::vector({3, 4, 5})}, {"b", Value::vector({3, 4, 5})}}, {}, "0", 0, 0}};
  return s;
}

NodeSpec reflectNode() {
  NodeSpec s = math::mathNode("reflect", "Mirror image of a direction about a normal (GLSL's reflect; N should be unit).",
                              "out = I - 2 dot(N, I) N");
  s.inputs = {ports::gen("incident", "the incident direction I (towards the surface)"),
              ports::gen("normal", "the surface normal N (unit for a true reflection)")};
  s.outputs = {ports::gen("out", "the reflected direction")};
  s.emit = [](EmitContext& ctx) { ctx.output(0, EmitContext::call("reflect", {ctx.input(0), ctx.input(1)})); };
  s.eval = [](EvalContext& ctx) {
    Type t = ctx.outputType(0);
    Value i = widened(ctx.input(0), t), n = widened(ctx.input(1), t);
    ctx.output(0, sub(i, scale(n, 2.0 * dot(n, i))));
  };
  s.cost = "a dot product and a multiply-add per component";
  s.conditionRoundings = 2;
  s.conditionWhy = "I - 2 (N.I) N cancels where the reflection is short against I and N (grazing incidence)";
  s.hardCases = {{"zero normal", {{"incident", Value::vector({1, -1, 0})}, {"normal", Value::vector({0, 0, 0})}}, {},
                  "I unchanged", -1, 1},
                 {"head-on", {{"incident", Value::vector({0, -1, 0})}, {"normal", up()}}, {}, "(0, 1, 0)", 0, 1}};
  return s;
}

NodeSpec refractNode() {
  NodeSpec s = math::mathNode(
      "refract",
      "Refracted direction by Snell's law (GLSL's refract: I and N unit); the zero vector under total internal "
      "reflection.",
      "k = 1 - eta^2 (1 - dot(N, I)^2); out = k < 0 ? 0 : eta I - (eta dot(N, I) + sqrt(k)) N");
  s.inputs = {ports::gen("incident", "the unit incident direction I (towards the surface)"),
              ports::gen("normal", "the unit surface normal N, facing against I"),
              ports::fixed("eta", Type::Float, Value::scalar(1.0 / 1.333),
                           "ratio of indices n1 / n2 (default air to water, 1 / 1.333)")};
  s.outputs = {ports::gen("out", "the refracted direction, or zero")};
  s.emit = [](EmitContext& ctx) {
    ctx.output(0, EmitContext::call("refract", {ctx.input(0), ctx.input(1), ctx.input(2)}));
  };
  s.eval = [](EvalContext& ctx) {
    Type t = ctx.outputType(0);
    Value i = widened(ctx.input(0), t), n = widened(ctx.input(1), t);
    double eta = ctx.input(2)[0], c = dot(n, i);
    double k = 1.0 - eta * eta * (1.0 - c * c);
    if (k < 0.0) {
      ctx.output(0, Value::ofType(t));
      return;
    }
    ctx.output(0, sub(scale(i, eta), scale(n, eta * c + std::sqrt(k))));
  };
  s.cost = "a dot product, a sqrt and a select";
  s.tolerance = 2e-6;
  // sqrt(k) has an infinite slope at the critical angle (k = 0).
  s.conditionRoundings = 2;
  s.conditionWhy = "grows as 1 / sqrt(k) towards the critical angle (k -> 0), where float32 rounding of I and N moves "
                   "the refracted direction fastest";
  auto at = [](double degrees) {
    double r = degrees * M_PI / 180.0;
    return Value::vector({std::sin(r), -std::cos(r), 0});
  };
  s.hardCases = {{"total internal reflection", {{"incident", at(60)}, {"normal", up()}, {"eta", Value::scalar(1.333)}}, {},
                  "the zero vector", 0, 0},
                 {"grazing from air", {{"incident", Value::vector({1, 0, 0})}, {"normal", up()}}, {}, "unit, finite", -1, 1},
                 {"head-on", {{"incident", at(0)}, {"normal", up()}}, {}, "straight through: (0, -1, 0)", -1, 0}};
  return s;
}

NodeSpec faceforwardNode() {
  NodeSpec s = math::mathNode("faceforward",
                              "N turned to face against I: N if dot(Nref, I) < 0, else -N (GLSL's faceforward).",
                              "out = dot(Nref, I) < 0 ? N : -N");
  s.inputs = {ports::gen("normal", "the vector N to orient"), ports::gen("incident", "the incident direction I"),
              ports::gen("reference", "the reference normal Nref (often N itself)")};
  s.outputs = {ports::gen("out", "N or -N")};
  s.emit = [](EmitContext& ctx) {
    ctx.output(0, EmitContext::call("faceforward", {ctx.input(0), ctx.input(1), ctx.input(2)}));
  };
  s.eval = [](EvalContext& ctx) {
    Type t = ctx.outputType(0);
    Value n = widened(ctx.input(0), t);
    ctx.output(0, dot(widened(ctx.input(2), t), widened(ctx.input(1), t)) < 0.0 ? n : scale(n, -1.0));
  };
  s.cost = "a dot product and a select";
  // The sign of the dot product flips where it is within rounding of 0.
  s.conditionRoundings = 2;
  s.conditionWhy = "jumps from N to -N where dot(Nref, I) is within float32 rounding of 0";
  s.hardCases = {{"perpendicular", {{"normal", up()}, {"incident", Value::vector({1, 0, 0})}, {"reference", up()}}, {},
                  "dot = 0 is not < 0: -N", -1, 0}};
  return s;
}

}  // namespace wg::nodes
