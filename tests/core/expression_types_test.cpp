// Types of formulas (core/expression_types.h): GLSL's rules for operators, swizzles,
// constructors, ?: and the built-ins, and an error at the right span for each way to break them.
#include <gtest/gtest.h>

#include <string>

#include "core/expression_parser.h"
#include "core/expression_types.h"

namespace wg::expr {
namespace {

const FormulaInputs kInputs = {{"f", Type::Float}, {"g", Type::Float}, {"u", Type::Vec2},
                               {"v", Type::Vec3}, {"w", Type::Vec3}, {"c", Type::Vec4}};

// The formula's type name, or "error@offset+length: message".
std::string typed(const std::string& formula, const FormulaInputs& inputs = kInputs) {
  auto parsed = parseFormula(formula);
  if (auto* e = std::get_if<FormulaError>(&parsed)) return "parse error: " + e->message;
  const Ast& ast = std::get<Ast>(parsed);
  auto r = typeFormula(ast, inputs);
  if (auto* e = std::get_if<FormulaError>(&r))
    return "error@" + std::to_string(e->span.offset) + "+" + std::to_string(e->span.length) + ": " + e->message;
  return std::string(typeName(std::get<std::vector<Type>>(r)[static_cast<std::size_t>(ast.root)]));
}

TEST(ExpressionTypes, OperatorsFollowGlsl) {
  EXPECT_EQ(typed("f * g + 1"), "float");
  EXPECT_EQ(typed("v * f"), "vec3");
  EXPECT_EQ(typed("2.0 - v"), "vec3");
  EXPECT_EQ(typed("v + w"), "vec3");
  EXPECT_EQ(typed("-c"), "vec4");
  EXPECT_EQ(typed("v + u"), "error@0+5: '+' mixes 'vec3' and 'vec2'; vectors must have the same size (a float goes with any)");
  EXPECT_EQ(typed("f < g ? v : w"), "vec3");
  EXPECT_EQ(typed("v.x >= 0.5 ? 1.0 : f"), "float");
  EXPECT_EQ(typed("f < g"), "error@0+5: the formula is a comparison (a bool); a node's output is a float or vector: choose values with '?:'");
  EXPECT_EQ(typed("(f < g) + 1"), "error@0+7: a comparison (a bool) cannot be an operand of '+'; use it as the condition of '?:'");
  EXPECT_EQ(typed("v < w ? f : g"), "error@0+1: '<' compares floats, not 'vec3' (compare components, such as v.x)");
  EXPECT_EQ(typed("f ? v : w"), "error@0+1: the condition of '?:' must be a comparison such as 'a < b', not a 'float'");
  EXPECT_EQ(typed("f < g ? v : 0.0"), "error@0+15: the two choices of '?:' have types 'vec3' and 'float'; they must be the same");
}

TEST(ExpressionTypes, SwizzlesAndConstructors) {
  EXPECT_EQ(typed("c.xyz"), "vec3");
  EXPECT_EQ(typed("c.bgra"), "vec4");
  EXPECT_EQ(typed("u.yx.x"), "float");
  EXPECT_EQ(typed("v.stp"), "vec3");
  EXPECT_EQ(typed("u.z"), "error@0+3: 'z' is past the end of a 'vec2'");
  EXPECT_EQ(typed("v.xg"), "error@0+4: '.xg' mixes the sets xyzw, rgba and stpq");
  EXPECT_EQ(typed("c.xyzwx"), "error@0+7: a swizzle picks at most 4 components, not 5");
  EXPECT_EQ(typed("v.q"), "error@0+3: 'q' is past the end of a 'vec3'");
  EXPECT_EQ(typed("v.k"), "error@0+3: 'k' is not a component: use x y z w, r g b a or s t p q");
  EXPECT_EQ(typed("f.x"), "error@0+3: a 'float' has no components to swizzle; '.x' needs a vector");
  EXPECT_EQ(typed("vec3(0.5)"), "vec3");
  EXPECT_EQ(typed("vec3(u, f)"), "vec3");
  EXPECT_EQ(typed("vec4(v, 1)"), "vec4");
  EXPECT_EQ(typed("vec3(c)"), "vec3");  // GLSL drops the surplus of the last argument
  EXPECT_EQ(typed("vec2(f)"), "vec2");
  EXPECT_EQ(typed("vec3(u)"), "error@0+7: vec3(...) needs 3 components, given 2");
  EXPECT_EQ(typed("vec2(f, g, f)"), "error@11+1: vec2(...) needs 2 components; this argument is past them");
  EXPECT_EQ(typed("vec2()"), "error@0+6: vec2(...) needs 2 components, given 0");
}

TEST(ExpressionTypes, BuiltinsByTheirSignatures) {
  EXPECT_EQ(typed("mix(v, w, f)"), "vec3");
  EXPECT_EQ(typed("mix(v, w, 1.0 - exp(-f * g))"), "vec3");
  EXPECT_EQ(typed("clamp(v, 0, 1)"), "vec3");
  EXPECT_EQ(typed("smoothstep(0.2, 0.8, u)"), "vec2");
  EXPECT_EQ(typed("step(0.5, c)"), "vec4");
  EXPECT_EQ(typed("atan(f)"), "float");
  EXPECT_EQ(typed("atan(u, u)"), "vec2");
  EXPECT_EQ(typed("length(v)"), "float");
  EXPECT_EQ(typed("dot(c, c)"), "float");
  EXPECT_EQ(typed("distance(u, u)"), "float");
  EXPECT_EQ(typed("cross(v, w)"), "vec3");
  EXPECT_EQ(typed("reflect(v, w)"), "vec3");
  EXPECT_EQ(typed("refract(v, w, 0.75)"), "vec3");
  EXPECT_EQ(typed("faceforward(v, w, v)"), "vec3");
  EXPECT_EQ(typed("normalize(v)"), "vec3");
  EXPECT_EQ(typed("cross(v, u)"), "error@9+1: 'cross' takes two 'vec3', not 'vec2'");
  EXPECT_EQ(typed("refract(v, w, u)"), "error@14+1: the third argument of 'refract' (the ratio of indices) is a 'float', not 'vec2'");
  EXPECT_EQ(typed("reflect(v, f)"), "error@11+1: 'reflect' takes arguments of one type: 'vec3' and 'float'");
  EXPECT_EQ(typed("mix(v, u, f)"), "error@0+12: 'mix' mixes 'vec3' and 'vec2'; vectors must have the same size (a float goes with any)");
}

TEST(ExpressionTypes, UnknownNamesGetSuggestions) {
  EXPECT_EQ(typed("mixx(v, w, f)"), "error@0+13: unknown function 'mixx' (did you mean 'mix'?)");
  EXPECT_EQ(typed("mix(v, w)"), "error@0+9: 'mix' takes 3 arguments, given 2");
  EXPECT_EQ(typed("atan(f, g, f)"), "error@0+13: 'atan' takes 1 or 2 arguments, given 3");
  EXPECT_EQ(typed("ww + v"), "error@0+2: unknown input 'ww' (did you mean 'w'?)");
  EXPECT_EQ(typed("x", {}), "error@0+1: unknown input 'x'; the node declares no inputs");
  EXPECT_EQ(typed("mix + 1"), "error@0+3: 'mix' is a function: call it, as in mix(...)");
  EXPECT_EQ(typed("v(1)"), "error@0+4: 'v' is an input, not a function");
}

TEST(ExpressionTypes, EveryFunctionNamesANodeOnce) {
  for (const auto& f : formulaFunctions()) {
    int same = 0;
    for (const auto& g : formulaFunctions()) same += (f.name == g.name && f.arity == g.arity);
    EXPECT_EQ(same, 1) << f.name << " with " << f.arity << " arguments";
    EXPECT_FALSE(f.node.empty()) << f.name;
  }
}

}  // namespace
}  // namespace wg::expr
