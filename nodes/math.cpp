// Math nodes: GLSL built-ins and operators on float/vec2/vec3/vec4 (Gen ports: a float
// splats to the widest input), plus swizzle, split, combine and remap. Where GLSL leaves a
// case undefined (pow of a negative base, equal smoothstep edges, normalize of zero) the
// node uses the library's safe form and says so.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/math_builders.h"
#include "nodes/node_library.h"
#include "nodes/port_builders.h"

namespace wg::nodes {
namespace {

using glsl::map1;
using glsl::map2;
using glsl::map3;
using math::binaryFunction;
using math::mathNode;
using math::swizzleIndex;
using math::typedName;
using math::unaryFunction;

// out = a OP b, component-wise.
template <class F>
NodeSpec binaryOperator(std::string type, std::string op, std::string summary, double defA, double defB, F f) {
  NodeSpec s = mathNode(std::move(type), std::move(summary), "out = a " + op + " b (component-wise)");
  s.inputs = {ports::gen("a", defA, "left operand"), ports::gen("b", defB, "right operand")};
  s.outputs = {ports::gen("out", "the result")};
  s.emit = [op](EmitContext& ctx) { ctx.output(0, "(" + ctx.input(0) + " " + op + " " + ctx.input(1) + ")"); };
  s.eval = [f](EvalContext& ctx) { ctx.output(0, map2(ctx.input(0), ctx.input(1), ctx.outputType(0), f)); };
  return s;
}

// True when a constant input has every component equal to x.
bool isAll(const std::optional<Value>& v, double x) {
  if (!v) return false;
  for (int i = 0; i < v->size(); ++i)
    if ((*v)[i] != x) return false;
  return true;
}

// The float vector type a Custom input carries, or an error for anything else.
bool requireFloatVector(InferContext& ctx, int port, int minComponents) {
  Type t = ctx.inputTypes[static_cast<size_t>(port)];
  if (!isFloatScalarOrVector(t) || componentCount(t) < minComponents) {
    ctx.error = "input '" + ctx.spec.inputs[static_cast<size_t>(port)].name + "' takes " +
                (minComponents > 1 ? "vec2, vec3 or vec4" : "float, vec2, vec3 or vec4") + ", not " +
                std::string(typeName(t));
    ctx.errorInput = port;
    return false;
  }
  return true;
}

std::string checkSwizzleMask(const nlohmann::json& v) {
  if (!v.is_string()) return "must be a string such as \"xyz\"";
  std::string m = v.get<std::string>();
  if (m.empty() || m.size() > 4) return "must have 1 to 4 components";
  for (char c : m)
    if (swizzleIndex(c) < 0) return "'" + m + "' may use only x, y, z, w (or r, g, b, a)";
  return "";
}

// The fact of clamp(x, lo, hi). GLSL leaves reversed bounds undefined; the two ways a GPU
// computes it, min(max(x, lo), hi) and max(min(x, hi), lo), are both non-decreasing in x,
// lo and hi, so each ranges from its value at the three lower ends to its value at the
// upper ends, and the fact covers both. A unit vector clamped component-wise need not stay
// unit.
ValueFact clampedFact(const ValueFact& x, const ValueFact& lo, const ValueFact& hi) {
  ValueFact f;
  f.lo = std::min(std::min(std::max(x.lo, lo.lo), hi.lo), std::max(std::min(x.lo, hi.lo), lo.lo));
  f.hi = std::max(std::min(std::max(x.hi, lo.hi), hi.hi), std::max(std::min(x.hi, hi.hi), lo.hi));
  return f;
}

}  // namespace

NodeSpec addNode() {
  NodeSpec s = binaryOperator("add", "+", "Sum.", 0, 0, [](double a, double b) { return a + b; });
  s.identity = [](const auto& c) { return isAll(c[1], 0) ? 0 : isAll(c[0], 0) ? 1 : -1; };
  return s;
}
NodeSpec subNode() {
  NodeSpec s = binaryOperator("sub", "-", "Difference.", 0, 0, [](double a, double b) { return a - b; });
  s.identity = [](const auto& c) { return isAll(c[1], 0) ? 0 : -1; };
  return s;
}
NodeSpec mulNode() {
  NodeSpec s = binaryOperator("mul", "*", "Product.", 1, 1, [](double a, double b) { return a * b; });
  s.identity = [](const auto& c) { return isAll(c[1], 1) ? 0 : isAll(c[0], 1) ? 1 : -1; };
  return s;
}
NodeSpec divNode() {
  NodeSpec s = binaryOperator("div", "/", "Quotient (IEEE: a division by zero gives an infinity, as on the GPU).",
                              0, 1, [](double a, double b) { return a / b; });
  s.identity = [](const auto& c) { return isAll(c[1], 1) ? 0 : -1; };
  return s;
}

NodeSpec mixNode() {
  NodeSpec s = mathNode("mix", "Linear blend of a and b by t.", "out = a * (1 - t) + b * t");
  s.inputs = {ports::gen("a", 0, "value at t = 0"), ports::gen("b", 1, "value at t = 1"),
              ports::gen("t", 0.5, "blend factor (a float or one per component)")};
  s.outputs = {ports::gen("out", "the blend")};
  s.identity = [](const auto& c) { return isAll(c[2], 0) ? 0 : isAll(c[2], 1) ? 1 : -1; };
  s.emit = [](EmitContext& ctx) { ctx.output(0, EmitContext::call("mix", {ctx.input(0), ctx.input(1), ctx.input(2)})); };
  s.eval = [](EvalContext& ctx) {
    ctx.output(0, map3(ctx.input(0), ctx.input(1), ctx.input(2), ctx.outputType(0), glsl::mix));
  };
  return s;
}

NodeSpec clampNode() {
  NodeSpec s = mathNode("clamp", "Limits x to [lo, hi].", "out = min(max(x, lo), hi)");
  s.inputs = {ports::gen("x", "the value"), ports::gen("lo", 0, "lower bound"), ports::gen("hi", 1, "upper bound")};
  s.outputs = {ports::gen("out", "the clamped value")};
  s.emit = [](EmitContext& ctx) {
    ValueFact x = ctx.inputFact(0), lo = ctx.inputFact(1), hi = ctx.inputFact(2);
    // Every value x can take already lies in [lo, hi] (value facts): the clamp is dead.
    if (x.lo >= lo.hi && x.hi <= hi.lo) return ctx.output(0, ctx.input(0));
    ctx.output(0, EmitContext::call("clamp", {ctx.input(0), ctx.input(1), ctx.input(2)}));
  };
  s.eval = [](EvalContext& ctx) {
    ctx.output(0, map3(ctx.input(0), ctx.input(1), ctx.input(2), ctx.outputType(0), glsl::clamp));
  };
  s.facts = [](const std::vector<ValueFact>& in, const ParsedOptions&) {
    return std::vector<ValueFact>{clampedFact(in[0], in[1], in[2])};
  };
  return s;
}

NodeSpec saturateNode() {
  NodeSpec s = mathNode("saturate", "Limits x to [0, 1].", "out = clamp(x, 0, 1)");
  s.inputs = {ports::gen("x", "the value")};
  s.outputs = {ports::gen("out", "the clamped value")};
  s.emit = [](EmitContext& ctx) {
    ValueFact x = ctx.inputFact(0);
    // Every value x can take already lies in [0, 1] (e.g. screen_uv): the clamp is dead.
    if (x.atLeast(0) && x.hi <= 1) return ctx.output(0, ctx.input(0));
    ctx.output(0, EmitContext::call("clamp", {ctx.input(0), "0.0", "1.0"}));
  };
  s.eval = [](EvalContext& ctx) { ctx.output(0, map1(ctx.input(0), ctx.outputType(0), glsl::saturate)); };
  s.facts = [](const std::vector<ValueFact>& in, const ParsedOptions&) {
    return std::vector<ValueFact>{clampedFact(in[0], {0, 0, false}, {1, 1, false})};
  };
  return s;
}

NodeSpec smoothstepNode() {
  NodeSpec s = mathNode("smoothstep", "Hermite step from edge0 to edge1; defined for equal and reversed edges.",
                        "t = clamp((x - e0) / (e1 - e0), 0, 1); out = t*t*(3 - 2t); e0 == e1 gives step(e0, x)");
  s.inputs = {ports::gen("edge0", 0, "where the step starts"), ports::gen("edge1", 1, "where it ends"),
              ports::gen("x", "the value")};
  s.outputs = {ports::gen("out", "0..1")};
  s.emit = [](EmitContext& ctx) {
    ctx.output(0, EmitContext::call(typedName("wg_smoothstep", ctx.outputType(0)), {ctx.input(0), ctx.input(1), ctx.input(2)}));
  };
  s.eval = [](EvalContext& ctx) {
    ctx.output(0, map3(ctx.input(0), ctx.input(1), ctx.input(2), ctx.outputType(0), glsl::safeSmoothstep));
  };
  s.cost = "about 8 instructions per component";
  s.hardCases = {{"equal edges", {{"edge0", Value::scalar(0.5)}, {"edge1", Value::scalar(0.5)}, {"x", Value::scalar(0.5)}},
                  {}, "a step at the edge: 1 at x = edge, never NaN", 0, 1},
                 {"reversed edges", {{"edge0", Value::scalar(1)}, {"edge1", Value::scalar(0)}, {"x", Value::scalar(0.25)}},
                  {}, "falls from 1 to 0, in [0, 1]", 0, 1}};
  return s;
}

NodeSpec powNode() {
  NodeSpec s = mathNode("pow", "x raised to y, with the base clamped at 0 (never NaN).",
                        "out = x > 0 ? exp2(min(y * log2(x), 127)) : (y > 0 ? 0 : 1) (a result past float's range "
                        "is 2^127 = 1.70e38, not +inf)");
  s.inputs = {ports::gen("x", "the base"), ports::gen("y", 1, "the exponent")};
  s.outputs = {ports::gen("out", "the power")};
  s.emit = [](EmitContext& ctx) {
    // 0 <= x <= 1 and y > 0 proven: native pow is defined there, cannot overflow, and
    // equals the safe one.
    ValueFact x = ctx.inputFact(0);
    bool known = x.atLeast(0) && x.hi <= 1 && ctx.inputFact(1).above(0);
    ctx.output(0, EmitContext::call(typedName(known ? "wg_pow_known_safe" : "wg_safe_pow", ctx.outputType(0)),
                                    {ctx.input(0), ctx.input(1)}));
  };
  s.eval = [](EvalContext& ctx) {
    ctx.output(0, map2(ctx.input(0), ctx.input(1), ctx.outputType(0), glsl::safePow));
  };
  s.facts = [](const std::vector<ValueFact>& in, const ParsedOptions&) {
    bool atMostOne = in[0].atLeast(0) && in[0].hi <= 1 && in[1].atLeast(0);
    return std::vector<ValueFact>{{0, atMostOne ? 1.0 : INFINITY, false}};
  };
  s.cost = "exp2 + log2 per component";
  s.tolerance = 1e-5;
  // GLSL asks log2 only for an absolute 2^-21 near 1: exp2(y log2 x) then errs by
  // |y| ln(2) 2^-21 = 5.5 |y| 2^-24 relative (pow(0.9999, 2048) on llvmpipe: 1.6e-4). That
  // is what rounding x by 6 units moves x^y by (x d/dx x^y = y x^y); y's own rounding moves
  // it by |y ln x| 2^-24, covered alike.
  s.conditionRoundings = 6;
  s.conditionWhy = "relative error grows as |y| 2^-21 (GLSL's log2 accuracy times the exponent: specular powers "
                   "of bases near 1) and as |y ln x| 2^-24";
  s.hardCases = {{"zero base", {{"x", Value::scalar(0)}, {"y", Value::scalar(3)}}, {}, "0, not NaN", 0, 0},
                 {"zero base, zero exponent", {{"x", Value::scalar(0)}, {"y", Value::scalar(0)}}, {}, "1", 1, 1},
                 {"tiny negative base", {{"x", Value::scalar(-1e-7)}, {"y", Value::scalar(0.5)}}, {}, "0, not NaN", 0, 0},
                 {"pow(10, 39)", {{"x", Value::scalar(10)}, {"y", Value::scalar(39)}}, {}, "2^127 = 1.70e38, not +inf",
                  1.7e38, 1.71e38}};
  return s;
}

NodeSpec dotNode() {
  NodeSpec s = mathNode("dot", "Dot product.", "out = sum(a[i] * b[i])");
  s.inputs = {ports::gen("a", "first vector"), ports::gen("b", "second vector")};
  s.outputs = {ports::fixed("out", Type::Float, "the dot product")};
  s.emit = [](EmitContext& ctx) { ctx.output(0, EmitContext::call("dot", {ctx.input(0), ctx.input(1)})); };
  s.eval = [](EvalContext& ctx) { ctx.output(0, Value::scalar(glsl::dot(ctx.input(0), ctx.input(1)))); };
  // A sum of products cancels for nearly perpendicular vectors far from the origin: the
  // inputs' rounding (2^-24 of each product) remains.
  s.conditionRoundings = 1;
  s.conditionWhy = "grows as |a| |b| / |a . b| for nearly perpendicular vectors (a sum of products that cancels)";
  return s;
}

NodeSpec crossNode() {
  NodeSpec s = mathNode("cross", "Cross product of two vec3 (float32 overflows where products pass 3.4e38).", "out = a x b");
  s.inputs = {ports::fixed("a", Type::Vec3, "first vector"), ports::fixed("b", Type::Vec3, "second vector")};
  s.outputs = {ports::fixed("out", Type::Vec3, "the cross product")};
  s.emit = [](EmitContext& ctx) { ctx.output(0, EmitContext::call("cross", {ctx.input(0), ctx.input(1)})); };
  s.eval = [](EvalContext& ctx) {
    const Value &a = ctx.input(0), &b = ctx.input(1);
    ctx.output(0, Value::vector({a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}));
  };
  // Each component is a difference of products: nearly parallel vectors far from the
  // origin cancel, and the inputs' rounding (2^-24 of each product) remains.
  s.conditionRoundings = 1;
  s.conditionWhy = "grows as |a| |b| / |a x b| for nearly parallel vectors (each component a difference of products)";
  return s;
}

NodeSpec normalizeNode() {
  NodeSpec s = mathNode("normalize",
                        "Unit vector; the zero vector stays zero instead of NaN, a vector shorter than 1e-15 comes out "
                        "shorter than 1 (the squared length is floored at 1e-30), and one with a component past 1.8e19 "
                        "is the zero vector (its float32 squared length overflows).",
                        "out = x * inversesqrt(max(dot(x, x), 1e-30))");
  s.inputs = {ports::gen("x", "the vector")};
  s.outputs = {ports::gen("out", "the unit vector")};
  // A safe normalisation: normalized (unit, or shorter for a vector under 1e-15; see
  // ValueFact), each component in [-1, 1] (a float becomes -1, 0 or 1).
  s.facts = [](const std::vector<ValueFact>&, const ParsedOptions&) { return std::vector<ValueFact>{{-1, 1, true}}; };
  s.emit = [](EmitContext& ctx) { ctx.output(0, EmitContext::call(typedName("wg_safe_normalize", ctx.outputType(0)), {ctx.input(0)})); };
  s.eval = [](EvalContext& ctx) { ctx.output(0, glsl::safeNormalize(ctx.input(0))); };
  s.hardCases = {{"zero vector", {{"x", Value::vector({0, 0, 0})}}, {}, "the zero vector, not NaN", 0, 0},
                 {"denormal vector", {{"x", Value::vector({1e-20, 0, 0})}}, {}, "finite, length <= 1", -1, 1}};
  return s;
}

NodeSpec lengthNode() {
  NodeSpec s = mathNode("length", "Euclidean length (float32 overflows past 1.8e19: +inf).", "out = sqrt(dot(x, x))");
  s.inputs = {ports::gen("x", "the vector")};
  s.outputs = {ports::fixed("out", Type::Float, "the length")};
  s.emit = [](EmitContext& ctx) { ctx.output(0, EmitContext::call("length", {ctx.input(0)})); };
  s.eval = [](EvalContext& ctx) { ctx.output(0, Value::scalar(glsl::length(ctx.input(0)))); };
  return s;
}

NodeSpec sinNode() {
  return unaryFunction("sin", "sin", "Sine (radians).", "out = sin(x)", [](double x) { return std::sin(x); });
}
NodeSpec cosNode() {
  return unaryFunction("cos", "cos", "Cosine (radians).", "out = cos(x)", [](double x) { return std::cos(x); });
}
NodeSpec absNode() {
  return unaryFunction("abs", "abs", "Absolute value.", "out = |x|", [](double x) { return std::fabs(x); });
}
NodeSpec minNode() {
  return binaryFunction("min", "min", "Smaller of a and b.", [](double a, double b) { return std::min(a, b); });
}
NodeSpec maxNode() {
  return binaryFunction("max", "max", "Larger of a and b.", [](double a, double b) { return std::max(a, b); });
}

namespace {

struct SwizzleOptions {
  std::string mask;  // as given: it names the output's components
};
SwizzleOptions parseSwizzleOptions(const OptionReader& o) { return {o.json("mask").get<std::string>()}; }

struct CombineOptions {
  Type type;
};
CombineOptions parseCombineOptions(const OptionReader& o) {
  return {o.choice<Type>("type", {{"vec2", Type::Vec2}, {"vec3", Type::Vec3}, {"vec4", Type::Vec4}})};
}

struct RemapOptions {
  bool clamped;
};
RemapOptions parseRemapOptions(const OptionReader& o) { return {o.flag("clamp")}; }

}  // namespace

NodeSpec swizzleNode() {
  NodeSpec s = mathNode("swizzle", "Picks and reorders components, as GLSL's .xyzw.", "out = x.<mask>");
  s.inputs = {ports::custom("x", "float or vector")};
  s.outputs = {ports::custom("out", "float or vecN, N = mask length")};
  s.options = {ports::checked(OptionSpec::Kind::Json, "mask", "xyz", checkSwizzleMask,
                              "1 to 4 of x y z w (or r g b a), e.g. \"xz\" or \"zyx\"")};
  s.parseOptions = optionParser(parseSwizzleOptions);
  s.infer = [](InferContext& ctx) {
    if (!requireFloatVector(ctx, 0, 1)) return;
    const std::string& m = ctx.options.as<SwizzleOptions>().mask;
    int n = componentCount(ctx.inputTypes[0]);
    for (char c : m)
      if (swizzleIndex(c) >= n) {
        ctx.error = "mask '" + m + "' reads component '" + std::string(1, c) + "' of a " +
                    std::string(typeName(ctx.inputTypes[0]));
        ctx.errorInput = 0;
        return;
      }
    ctx.outputTypes[0] = floatVector(static_cast<int>(m.size()));
  };
  s.emit = [](EmitContext& ctx) {
    const std::string& m = ctx.options<SwizzleOptions>().mask;
    if (ctx.inputType(0) == Type::Float) {  // GLSL 330 has no scalar swizzles
      ctx.output(0, m.size() == 1 ? ctx.input(0) : std::string(typeName(ctx.outputType(0))) + "(" + ctx.input(0) + ")");
      return;
    }
    std::string xyzw;
    for (char c : m) xyzw += "xyzw"[swizzleIndex(c)];
    ctx.output(0, ctx.input(0) + "." + xyzw);
  };
  s.eval = [](EvalContext& ctx) {
    const std::string& m = ctx.options<SwizzleOptions>().mask;
    Value r = Value::ofType(ctx.outputType(0));
    for (size_t i = 0; i < m.size(); ++i) r[static_cast<int>(i)] = ctx.input(0)[swizzleIndex(m[i])];
    ctx.output(0, r);
  };
  s.cost = "free (a register swizzle)";
  return s;
}

NodeSpec splitNode() {
  NodeSpec s = mathNode("split", "Splits a vector into its components (only those it has).", "x = v.x, y = v.y, ...");
  s.inputs = {ports::custom("v", "vec2, vec3 or vec4")};
  s.outputs = {ports::custom("x", "first component"), ports::custom("y", "second component"),
               ports::custom("z", "third component (vec3, vec4)"), ports::custom("w", "fourth component (vec4)")};
  s.infer = [](InferContext& ctx) {
    if (!requireFloatVector(ctx, 0, 2)) return;
    int n = componentCount(ctx.inputTypes[0]);
    for (int i = 0; i < 4; ++i) ctx.outputTypes[static_cast<size_t>(i)] = i < n ? Type::Float : Type::Invalid;
  };
  s.emit = [](EmitContext& ctx) {
    int n = componentCount(ctx.inputType(0));
    GlslExpr v = ctx.input(0);
    for (int i = 0; i < n; ++i) ctx.output(i, v + "." + "xyzw"[i]);
  };
  s.eval = [](EvalContext& ctx) {
    int n = ctx.input(0).size();
    for (int i = 0; i < n; ++i) ctx.output(i, Value::scalar(ctx.input(0)[i]));
  };
  s.cost = "free";
  return s;
}

NodeSpec combineNode() {
  NodeSpec s = mathNode("combine", "Builds a vector from floats.", "out = vecN(x, y[, z[, w]])");
  s.inputs = {ports::fixed("x", Type::Float, Value::scalar(0), "first component"),
              ports::fixed("y", Type::Float, Value::scalar(0), "second component"),
              ports::fixed("z", Type::Float, Value::scalar(0), "third component (vec3, vec4)"),
              ports::fixed("w", Type::Float, Value::scalar(1), "fourth component (vec4)")};
  s.outputs = {ports::custom("out", "the vector")};
  s.options = {ports::choice("type", {"vec2", "vec3", "vec4"}, "vec3", "the vector type built")};
  s.parseOptions = optionParser(parseCombineOptions);
  s.infer = [](InferContext& ctx) { ctx.outputTypes[0] = ctx.options.as<CombineOptions>().type; };
  s.emit = [](EmitContext& ctx) {
    int n = componentCount(ctx.outputType(0));
    GlslExpr e(typeName(ctx.outputType(0)));
    e += "(";
    for (int i = 0; i < n; ++i) e += (i ? ", " : "") + ctx.input(i);
    ctx.output(0, e + ")");
  };
  s.eval = [](EvalContext& ctx) {
    Value r = Value::ofType(ctx.outputType(0));
    for (int i = 0; i < r.size(); ++i) r[i] = ctx.input(i)[0];
    ctx.output(0, r);
  };
  s.cost = "free";
  return s;
}

NodeSpec remapNode() {
  NodeSpec s = mathNode("remap", "Maps x from [in_min, in_max] to [out_min, out_max], optionally clamped.",
                        "t = (x - in_min) / (in_max - in_min) (0 when in_max == in_min); out = mix(out_min, out_max, t)");
  s.inputs = {ports::gen("x", "the value"), ports::gen("in_min", 0, "source range start"),
              ports::gen("in_max", 1, "source range end"), ports::gen("out_min", 0, "target range start"),
              ports::gen("out_max", 1, "target range end")};
  s.outputs = {ports::gen("out", "the remapped value")};
  s.options = {ports::flag("clamp", false, "clamp t to [0, 1]")};
  s.parseOptions = optionParser(parseRemapOptions);
  s.emit = [](EmitContext& ctx) {
    // A proven non-empty source range (the ranges of in_min and in_max are disjoint)
    // makes the empty-range select dead.
    // The gap at least FLT_MIN: then b - a cannot round or flush to zero in float.
    ValueFact a = ctx.inputFact(1), b = ctx.inputFact(2);
    const double gap = static_cast<double>(std::numeric_limits<float>::min());
    bool nonempty = b.lo - a.hi >= gap || a.lo - b.hi >= gap;
    std::string fn = typedName(std::string(ctx.options<RemapOptions>().clamped ? "wg_remap_clamped" : "wg_remap") +
                                   (nonempty ? "_nonempty" : ""),
                               ctx.outputType(0));
    ctx.output(0, EmitContext::call(fn, {ctx.input(0), ctx.input(1), ctx.input(2), ctx.input(3), ctx.input(4)}));
  };
  s.eval = [](EvalContext& ctx) {
    bool clamped = ctx.options<RemapOptions>().clamped;
    Value r = Value::ofType(ctx.outputType(0));
    for (int i = 0; i < r.size(); ++i) {
      double x = ctx.input(0)[i], a = ctx.input(1)[i], b = ctx.input(2)[i];
      double t = b == a ? 0.0 : (x - a) / (b - a);
      if (clamped) t = glsl::saturate(t);
      r[i] = glsl::mix(ctx.input(3)[i], ctx.input(4)[i], t);
    }
    ctx.output(0, r);
  };
  s.cost = "about 6 instructions per component";
  s.hardCases = {{"empty source range", {{"x", Value::scalar(3)}, {"in_min", Value::scalar(2)}, {"in_max", Value::scalar(2)}},
                  {}, "out_min, not a division by zero", 0, 0}};
  return s;
}

}  // namespace wg::nodes
