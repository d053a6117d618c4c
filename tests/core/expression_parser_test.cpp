// The expression language's lexer and parser (core/expression_parser.h): precedence and
// associativity as GLSL's, spans of every node, each error's span and message, and the
// nesting cap that bounds the parser's stack whatever the input.
#include <gtest/gtest.h>

#include <string>

#include "core/expression_parser.h"

namespace wg::expr {
namespace {

// The tree in prefix form: (+ a (* b c)), numbers as written, calls as (name args...).
std::string prefix(const Ast& ast, int i) {
  const Node& n = ast.nodes[static_cast<std::size_t>(i)];
  auto operands = [&] {
    std::string s;
    for (int o : n.operands) s += " " + prefix(ast, o);
    return s;
  };
  switch (n.kind) {
    case NodeKind::Number:
    case NodeKind::Name: return n.text;
    case NodeKind::Negate: return "(neg" + operands() + ")";
    case NodeKind::Binary:
    case NodeKind::Compare: return "(" + n.text + operands() + ")";
    case NodeKind::Select: return "(?" + operands() + ")";
    case NodeKind::Call: return "(" + n.text + operands() + ")";
    case NodeKind::Swizzle: return "(." + n.text + operands() + ")";
  }
  return "?";
}

std::string parsed(const std::string& formula) {
  auto r = parseFormula(formula);
  if (auto* e = std::get_if<FormulaError>(&r)) return "error@" + std::to_string(e->span.offset) + ": " + e->message;
  const Ast& ast = std::get<Ast>(r);
  return prefix(ast, ast.root);
}

FormulaError errorOf(const std::string& formula) {
  auto r = parseFormula(formula);
  EXPECT_TRUE(std::holds_alternative<FormulaError>(r)) << formula;
  return std::holds_alternative<FormulaError>(r) ? std::get<FormulaError>(r) : FormulaError{};
}

TEST(ExpressionParser, PrecedenceAndAssociativityFollowGlsl) {
  EXPECT_EQ(parsed("a + b * c"), "(+ a (* b c))");
  EXPECT_EQ(parsed("a - b - c"), "(- (- a b) c)");  // left-associative
  EXPECT_EQ(parsed("a / b / c"), "(/ (/ a b) c)");
  EXPECT_EQ(parsed("(a + b) * c"), "(* (+ a b) c)");
  EXPECT_EQ(parsed("-a * b"), "(* (neg a) b)");      // unary binds tighter than *
  EXPECT_EQ(parsed("- -a"), "(neg (neg a))");
  EXPECT_EQ(parsed("+a"), "a");
  EXPECT_EQ(parsed("-v.x"), "(neg (.x v))");         // the swizzle binds tighter than unary
  EXPECT_EQ(parsed("a + b < c * d"), "(< (+ a b) (* c d))");
  EXPECT_EQ(parsed("a < b ? c : d"), "(? (< a b) c d)");
  EXPECT_EQ(parsed("a ? b : c ? d : e"), "(? a b (? c d e))");  // right-associative
  EXPECT_EQ(parsed("a ? b ? c : d : e"), "(? a (? b c d) e)");
  EXPECT_EQ(parsed("mix(shallow, deep, 1.0 - exp(-k * d))"), "(mix shallow deep (- 1.0 (exp (* (neg k) d))))");
  EXPECT_EQ(parsed("vec3(1, 2, 3).zy.x"), "(.x (.zy (vec3 1 2 3)))");
  EXPECT_EQ(parsed("f()"), "(f)");
  EXPECT_EQ(parsed("a <= b"), "(<= a b)");
  EXPECT_EQ(parsed("a != b"), "(!= a b)");
}

TEST(ExpressionParser, NumbersAreGlslFloatLiterals) {
  auto value = [](const std::string& f) {
    auto r = parseFormula(f);
    const Ast& ast = std::get<Ast>(r);
    return ast.nodes[static_cast<std::size_t>(ast.root)].value;
  };
  EXPECT_EQ(value("1"), 1.0);
  EXPECT_EQ(value("1."), 1.0);
  EXPECT_EQ(value(".5"), 0.5);
  EXPECT_EQ(value("1.5e3"), 1500.0);
  EXPECT_EQ(value("2E-3"), 0.002);
  EXPECT_EQ(value("3.4e38"), 3.4e38);
  EXPECT_NE(errorOf("1e39").message.find("too large for a float"), std::string::npos);
  EXPECT_NE(errorOf("1e").message.find("no digits in its exponent"), std::string::npos);
  EXPECT_NE(errorOf("2x").message.find("a number runs into a name"), std::string::npos);
}

TEST(ExpressionParser, EveryNodeSpansItsText) {
  const std::string f = "mix(a, (b + c), -d.x)";
  auto r = parseFormula(f);
  const Ast& ast = std::get<Ast>(r);
  auto text = [&](int i) {
    const Span& s = ast.nodes[static_cast<std::size_t>(i)].span;
    return f.substr(s.offset, s.length);
  };
  const Node& call = ast.nodes[static_cast<std::size_t>(ast.root)];
  EXPECT_EQ(text(ast.root), f);
  ASSERT_EQ(call.operands.size(), 3u);
  EXPECT_EQ(text(call.operands[0]), "a");
  EXPECT_EQ(text(call.operands[1]), "(b + c)");
  EXPECT_EQ(text(call.operands[2]), "-d.x");
  for (std::size_t i = 0; i < ast.nodes.size(); ++i)
    for (int o : ast.nodes[i].operands) EXPECT_LT(o, static_cast<int>(i)) << "operands come before their user";
}

TEST(ExpressionParser, ErrorsNameWhatWasFoundWhere) {
  struct Case {
    std::string formula;
    std::size_t offset;
    std::string message;
  };
  for (const Case& c : std::vector<Case>{
           {"a +", 3, "the formula ends where a value was expected"},
           {"a + * b", 4, "expected a value, found '*'"},
           {"mix(a, b", 8, "expected ',' or ')' in the call of 'mix', found end of formula"},
           {"(a + b", 6, "expected ')' to close the '(' at character 1, found end of formula"},
           {"a ? b", 5, "expected ':' between the two choices of '?', found end of formula"},
           {"a b", 2, "unexpected name 'b' after the formula"},
           {"a = b", 2, "unexpected character '='"},
           {"a && b", 2, "unexpected character '&'"},
           {"v.1", 1, "unexpected number '.1' after the formula"},  // ".1" is a float, as in GLSL
           {"v.(x)", 2, "expected a swizzle such as 'xy' after '.', found '('"},
           {"a\x01", 1, "unexpected character '\\x01'"},
           // A multi-byte character is named whole (it was its first byte, '\xc3').
           {"x + \xc3\xa9", 4, "unexpected character '\\xc3\\xa9' (U+00E9)"},
           {"x + \xe2\x82\xac", 4, "unexpected character '\\xe2\\x82\\xac' (U+20AC)"},
           {"x + \xc3", 4, "unexpected character '\\xc3'"},  // cut short: the byte alone
           {"", 0, "the formula ends where a value was expected"},
       }) {
    FormulaError e = errorOf(c.formula);
    EXPECT_EQ(e.span.offset, c.offset) << c.formula;
    EXPECT_EQ(e.message, c.message) << c.formula;
  }
}

TEST(ExpressionParser, NestingIsCappedSoTheStackIsBounded) {
  auto nested = [](int levels) { return std::string(static_cast<std::size_t>(levels), '(') + "x" +
                                        std::string(static_cast<std::size_t>(levels), ')'); };
  EXPECT_EQ(parsed(nested(kMaxFormulaNesting)), "x");
  FormulaError e = errorOf(nested(kMaxFormulaNesting + 1));
  EXPECT_EQ(e.span.offset, static_cast<std::size_t>(kMaxFormulaNesting));  // the first '(' too many
  EXPECT_NE(e.message.find("more than 64 levels deep"), std::string::npos) << e.message;
  // Calls and ?: branches count too; a million brackets is refused without a deep stack.
  std::string calls;
  for (int i = 0; i <= kMaxFormulaNesting; ++i) calls += "f(";
  EXPECT_NE(errorOf(calls + "x").message.find("levels deep"), std::string::npos);
  std::string ternaries = "a";
  for (int i = 0; i <= kMaxFormulaNesting; ++i) ternaries = "c ? (" + ternaries + ") : d";
  EXPECT_NE(errorOf(ternaries).message.find("levels deep"), std::string::npos);
  EXPECT_NE(errorOf(std::string(1000000, '(')).message.find("longer than"), std::string::npos);
  EXPECT_NE(errorOf(std::string(10000, '(')).message.find("levels deep"), std::string::npos);
}

TEST(ExpressionParser, LongChainsAreLoopsNotRecursion) {
  // 4,000 terms and 4,000 signs: within the length cap, no nesting at all.
  std::string sum = "a";
  for (int i = 0; i < 4000; ++i) sum += "+a";
  auto r = parseFormula(sum);
  ASSERT_TRUE(std::holds_alternative<Ast>(r));
  EXPECT_EQ(std::get<Ast>(r).nodes.size(), 8001u);
  auto signs = parseFormula(std::string(4000, '-') + "a");
  ASSERT_TRUE(std::holds_alternative<Ast>(signs));
  EXPECT_EQ(std::get<Ast>(signs).nodes.size(), 4001u);
}

}  // namespace
}  // namespace wg::expr
