#include "core/expression_lexer.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace wg::expr {
namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isIdentifierStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool isIdentifierChar(char c) { return isIdentifierStart(c) || isDigit(c); }

// The length of the decimal float literal at the start of `s` (digits, an optional
// fraction, an optional exponent with at least one digit); 0 when there is none.
std::size_t numberLength(std::string_view s) {
  std::size_t i = 0, digits = 0;
  while (i < s.size() && isDigit(s[i])) ++i, ++digits;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && isDigit(s[i])) ++i, ++digits;
  }
  if (digits == 0) return 0;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    std::size_t j = i + 1;
    if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
    if (j >= s.size() || !isDigit(s[j])) return std::string_view::npos;  // "1e", "2e+"
    while (j < s.size() && isDigit(s[j])) ++j;
    i = j;
  }
  return i;
}

}  // namespace

// The bytes of the UTF-8 sequence starting at `at` (1 for ASCII or a byte that starts no
// well-formed sequence), so an unexpected 'é' is named whole, not by its first byte.
std::size_t utf8SequenceLength(std::string_view s, std::size_t at) {
  auto u = static_cast<unsigned char>(s[at]);
  std::size_t n = u >= 0xf0 && u <= 0xf4 ? 4 : u >= 0xe0 ? 3 : u >= 0xc2 && u <= 0xdf ? 2 : 1;
  if (u >= 0xf5) n = 1;
  if (at + n > s.size()) return 1;
  for (std::size_t k = 1; k < n; ++k)
    if ((static_cast<unsigned char>(s[at + k]) & 0xc0) != 0x80) return 1;
  return n;
}

// " (U+00E9)" for a multi-byte UTF-8 sequence, "" otherwise.
std::string codePointNote(std::string_view seq) {
  if (seq.size() < 2) return "";
  unsigned cp = static_cast<unsigned char>(seq[0]) & (0x7fu >> seq.size());
  for (std::size_t k = 1; k < seq.size(); ++k) cp = (cp << 6) | (static_cast<unsigned char>(seq[k]) & 0x3fu);
  char buf[16];
  std::snprintf(buf, sizeof buf, " (U+%04X)", cp);
  return buf;
}

std::string quoteToken(std::string_view text) {
  std::string out = "'";
  for (char c : text) {
    auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7f) {
      out += c;
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", u);
      out += buf;
    }
  }
  return out + "'";
}

std::vector<Token> tokenize(std::string_view formula, std::optional<FormulaError>* error) {
  std::vector<Token> tokens;
  std::size_t i = 0;
  auto fail = [&](std::size_t at, std::size_t length, std::string message) {
    *error = FormulaError{{at, length}, std::move(message)};
    return std::vector<Token>{};
  };
  while (i < formula.size()) {
    char c = formula[i];
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
      ++i;
      continue;
    }
    Token t;
    t.span.offset = i;
    if (isDigit(c) || (c == '.' && i + 1 < formula.size() && isDigit(formula[i + 1]))) {
      std::size_t n = numberLength(formula.substr(i));
      if (n == std::string_view::npos) {
        std::size_t end = i;
        while (end < formula.size() && (isIdentifierChar(formula[end]) || formula[end] == '.' || formula[end] == '+' ||
                                         formula[end] == '-'))
          ++end;
        return fail(i, end - i, "the number " + quoteToken(formula.substr(i, end - i)) + " has no digits in its exponent");
      }
      t.kind = TokenKind::Number;
      t.text = std::string(formula.substr(i, n));
      t.number = std::strtod(t.text.c_str(), nullptr);
      // A literal must be a float32 value, as it will be in the shader.
      if (!std::isfinite(t.number) || std::fabs(t.number) > 3.4028234663852886e38)
        return fail(i, n, "the number " + quoteToken(t.text) + " is too large for a float");
      if (n < formula.size() - i && isIdentifierStart(formula[i + n]))
        return fail(i, n + 1, "a number runs into a name at " + quoteToken(formula.substr(i, n + 1)));
    } else if (isIdentifierStart(c)) {
      std::size_t n = 1;
      while (i + n < formula.size() && isIdentifierChar(formula[i + n])) ++n;
      t.kind = TokenKind::Identifier;
      t.text = std::string(formula.substr(i, n));
    } else {
      static const char* const kTwo[] = {"<=", ">=", "==", "!="};
      static const std::string_view kOne = "+-*/(),?:.<>";
      t.kind = TokenKind::Symbol;
      for (const char* two : kTwo)
        if (formula.substr(i, 2) == two) t.text = two;
      if (t.text.empty() && kOne.find(c) != std::string_view::npos) t.text = std::string(1, c);
      if (t.text.empty()) {
        std::size_t n = utf8SequenceLength(formula, i);
        return fail(i, n, "unexpected character " + quoteToken(formula.substr(i, n)) + codePointNote(formula.substr(i, n)));
      }
    }
    t.span.length = t.text.size();
    i += t.text.size();
    tokens.push_back(std::move(t));
  }
  Token end;
  end.span = {formula.size(), 0};
  tokens.push_back(end);
  return tokens;
}

}  // namespace wg::expr
