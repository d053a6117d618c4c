#pragma once
// Tokens of an `expression` node's formula (core/expression_ast.h).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/expression_ast.h"

namespace wg::expr {

enum class TokenKind { Number, Identifier, Symbol, End };

struct Token {
  TokenKind kind = TokenKind::End;
  std::string text;  // as written ("1.5e3", "mix", "<=")
  double number = 0;  // for a Number
  Span span;
};

// Where the formula is wrong and how: a span of it and a message naming what was found.
struct FormulaError {
  Span span;
  std::string message;
};

// The formula's tokens, ending with one End token; or the first character that starts
// none (a stray '#', a number such as "1e" or "1e999" that has no float value).
std::vector<Token> tokenize(std::string_view formula, std::optional<FormulaError>* error);

// `text` as a quoted token for messages: printable ASCII as is, other bytes as \xNN.
std::string quoteToken(std::string_view text);

}  // namespace wg::expr
