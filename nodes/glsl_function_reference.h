#pragma once
// A GLSL function node's double-precision reference: one formula per output, in the
// expression language of the `expression` node, over the function's inputs. Each formula
// is lowered into ops of the math nodes once, when the node is made; the node's eval runs
// those ops through their own double references, so probe, check and the hard-case sweep
// treat the function like any node with a reference. The node's error bound is that of the
// ops its formulas lower into, as an expression's is (accuracy/error_bound.h): the GLSL
// computes the same maths in float32, so the formula's conditioning is what float32
// rounding of its inputs does to it (a sine of a huge phase), not a fault of the function.
#include <functional>
#include <string>
#include <variant>

#include <nlohmann/json.hpp>

#include "core/node_spec.h"
#include "nodes/glsl_function_check.h"

namespace wg {

struct FunctionReferenceFault {
  bool syntax = false;  // a formula that does not parse (else: it names, calls or types wrongly)
  std::string message;
};

struct FunctionReference {
  std::function<void(EvalContext&)> eval;
  double tolerance = 0;           // the largest NodeSpec::tolerance of the lowered ops
  double conditionRoundings = 0;  // the largest NodeSpec::conditionRoundings of the lowered ops
};

// The eval of the node and its bound, from its `reference` option (an object: output name
// -> formula, one for every output), or why the option cannot serve.
std::variant<FunctionReference, FunctionReferenceFault> makeFunctionReference(
    const FunctionSignature& signature, const nlohmann::json& reference);

}  // namespace wg
