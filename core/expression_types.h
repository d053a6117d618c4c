#pragma once
// Types of an `expression` node's formula, by GLSL's rules: each syntax-tree node
// (core/expression_ast.h) gets float, vec2, vec3, vec4 or (a comparison) bool, or the
// first error with the span it is about. The functions a formula may call are the GLSL
// built-ins the math nodes implement; each names the node it is computed by.
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "core/expression_ast.h"
#include "core/expression_lexer.h"
#include "core/types.h"

namespace wg::expr {

// How a function's result type follows from its arguments' types (T: float or vecN).
enum class Signature {
  Generic,        // each argument T or float, the vectors all one T; the result T (float if all float)
  ToFloat,        // the arguments as Generic, the result float (dot, length, distance)
  Cross,          // vec3, vec3 -> vec3
  Refract,        // T, T, float -> T
  SameVectors,    // every argument the same T (reflect, faceforward) -> T
};

struct FormulaFunction {
  std::string_view name;  // as written in the formula
  int arity;
  std::string_view node;  // the registry node that computes it
  Signature signature;
};

// Every function a formula may call, by name and arity (atan has one and two arguments).
const std::vector<FormulaFunction>& formulaFunctions();

// The declared inputs: name and type (float or vecN).
using FormulaInputs = std::vector<std::pair<std::string, Type>>;

// One type per node of `ast`; or the first error.
std::variant<std::vector<Type>, FormulaError> typeFormula(const Ast& ast, const FormulaInputs& inputs);

}  // namespace wg::expr
