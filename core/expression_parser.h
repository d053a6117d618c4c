#pragma once
// The parser of an `expression` node's formula: tokens (core/expression_lexer.h) to a
// syntax tree (core/expression_ast.h), or the first error with its span.
//
// Grammar, loosest first (GLSL's precedence):
//   formula  := select
//   select   := compare ('?' select ':' select)?
//   compare  := sum (('<' | '<=' | '>' | '>=' | '==' | '!=') sum)*
//   sum      := product (('+' | '-') product)*
//   product  := unary (('*' | '/') unary)*
//   unary    := ('-' | '+')* postfix
//   postfix  := primary ('.' identifier)*
//   primary  := number | identifier | identifier '(' (select (',' select)*)? ')' | '(' select ')'
// Chains (a + b + c, - - x, v.xy.x) are loops; only brackets, calls and ?: branches go
// deeper, and their nesting is capped, so the parser's stack is bounded whatever the input.
#include <string_view>
#include <variant>

#include "core/expression_ast.h"
#include "core/expression_lexer.h"

namespace wg::expr {

inline constexpr int kMaxFormulaNesting = 64;             // brackets, calls and ?: inside each other
inline constexpr std::size_t kMaxFormulaLength = 16384;   // bytes of formula text

std::variant<Ast, FormulaError> parseFormula(std::string_view formula);

}  // namespace wg::expr
