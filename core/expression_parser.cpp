#include "core/expression_parser.h"

#include <initializer_list>
#include <optional>
#include <string_view>
#include <utility>

namespace wg::expr {
namespace {

// Thrown inside the parser only, caught by parseFormula: the first error ends the parse.
struct ParseStop {
  FormulaError error;
};

class Parser {
 public:
  explicit Parser(std::vector<Token> tokens) : tokens_(std::move(tokens)) {}

  Ast parse() {
    ast_.root = select(0);
    if (peek().kind != TokenKind::End) fail(peek().span, "unexpected " + describe(peek()) + " after the formula");
    return std::move(ast_);
  }

 private:
  const Token& peek() const { return tokens_[pos_]; }
  bool atSymbol(std::string_view s) const { return peek().kind == TokenKind::Symbol && peek().text == s; }
  const Token& next() { return tokens_[pos_ < tokens_.size() - 1 ? pos_++ : pos_]; }

  [[noreturn]] static void fail(Span span, std::string message) { throw ParseStop{{span, std::move(message)}}; }

  static std::string describe(const Token& t) {
    switch (t.kind) {
      case TokenKind::End: return "end of formula";
      case TokenKind::Number: return "number " + quoteToken(t.text);
      case TokenKind::Identifier: return "name " + quoteToken(t.text);
      case TokenKind::Symbol: return quoteToken(t.text);
    }
    return quoteToken(t.text);
  }

  // One level deeper (a bracket, a call's arguments, a ?: branch), refused past the cap.
  void enter(int depth, const Token& at) const {
    if (depth >= kMaxFormulaNesting)
      fail(at.span, "the formula nests brackets, calls and ?: more than " + std::to_string(kMaxFormulaNesting) +
                        " levels deep");
  }

  void expect(std::string_view symbol, const std::string& what) {
    if (!atSymbol(symbol)) fail(peek().span, "expected " + quoteToken(symbol) + " " + what + ", found " + describe(peek()));
    next();
  }

  int add(Node n) {
    ast_.nodes.push_back(std::move(n));
    return static_cast<int>(ast_.nodes.size()) - 1;
  }

  Span spanOf(int a, int b) const {
    const Span& x = ast_.nodes[static_cast<std::size_t>(a)].span;
    const Span& y = ast_.nodes[static_cast<std::size_t>(b)].span;
    return {x.offset, y.offset + y.length - x.offset};
  }

  int binary(NodeKind kind, const std::string& op, int left, int right) {
    Node n;
    n.kind = kind;
    n.text = op;
    n.operands = {left, right};
    n.span = spanOf(left, right);
    return add(std::move(n));
  }

  int select(int depth) {
    int condition = compare(depth);
    if (!atSymbol("?")) return condition;
    enter(depth, peek());
    next();
    int whenTrue = select(depth + 1);
    expect(":", "between the two choices of '?'");
    int whenFalse = select(depth + 1);
    Node n;
    n.kind = NodeKind::Select;
    n.operands = {condition, whenTrue, whenFalse};
    n.span = spanOf(condition, whenFalse);
    return add(std::move(n));
  }

  // One left-associative level: operands from `operand`, joined by any of `ops`.
  template <class Operand>
  int leftAssociative(int depth, NodeKind kind, std::initializer_list<std::string_view> ops, Operand operand) {
    int left = (this->*operand)(depth);
    auto atOne = [&] {
      for (std::string_view op : ops)
        if (atSymbol(op)) return true;
      return false;
    };
    while (atOne()) {
      std::string op = next().text;
      left = binary(kind, op, left, (this->*operand)(depth));
    }
    return left;
  }

  int compare(int depth) {
    return leftAssociative(depth, NodeKind::Compare, {"<", "<=", ">", ">=", "==", "!="}, &Parser::sum);
  }
  int sum(int depth) { return leftAssociative(depth, NodeKind::Binary, {"+", "-"}, &Parser::product); }
  int product(int depth) { return leftAssociative(depth, NodeKind::Binary, {"*", "/"}, &Parser::unary); }

  int unary(int depth) {
    std::vector<std::size_t> minus;  // offsets of the '-' signs, outermost first
    while (atSymbol("-") || atSymbol("+")) {
      if (peek().text == "-") minus.push_back(peek().span.offset);
      next();
    }
    int operand = postfix(depth);
    for (auto it = minus.rbegin(); it != minus.rend(); ++it) {
      Node n;
      n.kind = NodeKind::Negate;
      n.operands = {operand};
      const Span& inner = ast_.nodes[static_cast<std::size_t>(operand)].span;
      n.span = {*it, inner.offset + inner.length - *it};
      operand = add(std::move(n));
    }
    return operand;
  }

  int postfix(int depth) {
    int operand = primary(depth);
    while (atSymbol(".")) {
      next();
      if (peek().kind != TokenKind::Identifier)
        fail(peek().span, "expected a swizzle such as 'xy' after '.', found " + describe(peek()));
      const Token& field = next();
      Node n;
      n.kind = NodeKind::Swizzle;
      n.text = field.text;
      n.operands = {operand};
      const Span& inner = ast_.nodes[static_cast<std::size_t>(operand)].span;
      n.span = {inner.offset, field.span.offset + field.span.length - inner.offset};
      operand = add(std::move(n));
    }
    return operand;
  }

  int primary(int depth) {
    const Token& t = peek();
    if (t.kind == TokenKind::Number) {
      next();
      Node n;
      n.kind = NodeKind::Number;
      n.text = t.text;
      n.value = t.number;
      n.span = t.span;
      return add(std::move(n));
    }
    if (t.kind == TokenKind::Identifier) {
      const Token& name = next();
      if (!atSymbol("(")) {
        Node n;
        n.kind = NodeKind::Name;
        n.text = name.text;
        n.span = name.span;
        return add(std::move(n));
      }
      enter(depth, peek());
      next();
      Node n;
      n.kind = NodeKind::Call;
      n.text = name.text;
      if (!atSymbol(")")) {
        n.operands.push_back(select(depth + 1));
        while (atSymbol(",")) {
          next();
          n.operands.push_back(select(depth + 1));
        }
      }
      if (!atSymbol(")"))
        fail(peek().span, "expected ',' or ')' in the call of " + quoteToken(name.text) + ", found " + describe(peek()));
      const Token& close = next();
      n.span = {name.span.offset, close.span.offset + 1 - name.span.offset};
      return add(std::move(n));
    }
    if (atSymbol("(")) {
      const Token& open = peek();
      enter(depth, open);
      next();
      int inner = select(depth + 1);
      if (!atSymbol(")")) fail(peek().span, "expected ')' to close the '(' at character " +
                                                std::to_string(open.span.offset + 1) + ", found " + describe(peek()));
      const Token& close = next();
      // The brackets belong to the span, so an error about the group underlines all of it.
      ast_.nodes[static_cast<std::size_t>(inner)].span = {open.span.offset, close.span.offset + 1 - open.span.offset};
      return inner;
    }
    fail(t.span, t.kind == TokenKind::End ? "the formula ends where a value was expected"
                                          : "expected a value, found " + describe(t));
  }

  std::vector<Token> tokens_;
  std::size_t pos_ = 0;
  Ast ast_;
};

}  // namespace

std::variant<Ast, FormulaError> parseFormula(std::string_view formula) {
  if (formula.size() > kMaxFormulaLength)
    return FormulaError{{kMaxFormulaLength, formula.size() - kMaxFormulaLength},
                        "the formula is longer than " + std::to_string(kMaxFormulaLength) + " characters"};
  std::optional<FormulaError> error;
  std::vector<Token> tokens = tokenize(formula, &error);
  if (error) return *error;
  try {
    return Parser(std::move(tokens)).parse();
  } catch (const ParseStop& stop) {
    return stop.error;
  }
}

}  // namespace wg::expr
