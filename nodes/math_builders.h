#pragma once
// The shapes the math nodes share (nodes/math*.cpp): a math NodeSpec with its defaults,
// component-wise unary and binary functions over Gen ports, and the library's per-type
// names. A node file uses these so that each node reads as its declaration.
#include <string>
#include <utility>

#include "core/emit_context.h"
#include "nodes/eval_math.h"
#include "nodes/port_builders.h"

namespace wg::nodes::math {

// A node of the math family, one ALU instruction per component and 1e-6 unless it says
// otherwise.
inline NodeSpec mathNode(std::string type, std::string summary, std::string formula) {
  NodeSpec s;
  s.type = std::move(type);
  s.family = "math";
  s.summary = std::move(summary);
  s.formula = std::move(formula);
  s.cost = "one ALU instruction per component";
  s.tolerance = 1e-6;
  return s;
}

// The library names one variant per type: wg_safe_pow_vec3.
inline std::string typedName(const std::string& fn, Type t) { return fn + "_" + std::string(typeName(t)); }

// out = fn(x) for a GLSL built-in `fn` (or a library function), component-wise.
template <class F>
NodeSpec unaryFunction(std::string type, std::string fn, std::string summary, std::string formula, F f) {
  NodeSpec s = mathNode(std::move(type), std::move(summary), std::move(formula));
  s.inputs = {ports::gen("x", "the argument")};
  s.outputs = {ports::gen("out", "the result")};
  s.emit = [fn](EmitContext& ctx) { ctx.output(0, EmitContext::call(fn, {ctx.input(0)})); };
  s.eval = [f](EvalContext& ctx) { ctx.output(0, glsl::map1(ctx.input(0), ctx.outputType(0), f)); };
  return s;
}

// out = fn(a, b), component-wise.
template <class F>
NodeSpec binaryFunction(std::string type, std::string fn, std::string summary, F f) {
  NodeSpec s = mathNode(std::move(type), std::move(summary), "out = " + fn + "(a, b) (component-wise)");
  s.inputs = {ports::gen("a", "first argument"), ports::gen("b", "second argument")};
  s.outputs = {ports::gen("out", "the result")};
  s.emit = [fn](EmitContext& ctx) { ctx.output(0, EmitContext::call(fn, {ctx.input(0), ctx.input(1)})); };
  s.eval = [f](EvalContext& ctx) { ctx.output(0, glsl::map2(ctx.input(0), ctx.input(1), ctx.outputType(0), f)); };
  return s;
}

// out = fn(x), component-wise, through the library's guarded form `guarded` (typed per
// variant) unless the input's value facts prove the guard dead (`rawIsSafe`), then the
// raw GLSL built-in `raw`: the two agree wherever the guard does nothing. `f` is the
// guarded form in double.
template <class F, class Dead>
NodeSpec guardedUnary(std::string type, std::string raw, std::string guarded, std::string summary, std::string formula,
                      Dead rawIsSafe, F f) {
  NodeSpec s = mathNode(std::move(type), std::move(summary), std::move(formula));
  s.inputs = {ports::gen("x", "the argument")};
  s.outputs = {ports::gen("out", "the result")};
  s.emit = [raw, guarded, rawIsSafe](EmitContext& ctx) {
    std::string fn = rawIsSafe(ctx.inputFact(0)) ? raw : typedName(guarded, ctx.outputType(0));
    ctx.output(0, EmitContext::call(fn, {ctx.input(0)}));
  };
  s.eval = [f](EvalContext& ctx) { ctx.output(0, glsl::map1(ctx.input(0), ctx.outputType(0), f)); };
  return s;
}

// Facts of a node whose single output always lies in [lo, hi], whatever its inputs.
inline auto alwaysWithin(double lo, double hi) {
  return [lo, hi](const std::vector<ValueFact>&, const ParsedOptions&) { return std::vector<ValueFact>{{lo, hi, false}}; };
}

// The component a swizzle letter names (x/r 0, y/g 1, z/b 2, w/a 3), -1 for another
// character: the swizzle node, and the surface query's form of it (codegen/query_ops.cpp).
inline int swizzleIndex(char c) {
  switch (c) {
    case 'x': case 'r': return 0;
    case 'y': case 'g': return 1;
    case 'z': case 'b': return 2;
    case 'w': case 'a': return 3;
    default: return -1;
  }
}

// A hard case with one input `x`.
inline HardCase hardX(std::string name, double x, std::string expectation, double lo, double hi) {
  return {std::move(name), {{"x", Value::scalar(x)}}, nlohmann::json::object(), std::move(expectation), lo, hi};
}

}  // namespace wg::nodes::math
