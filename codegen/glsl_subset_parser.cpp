// A recursive-descent parser of the GLSL subset watergraph writes (codegen/glsl_subset.h).
// Precedence follows the GLSL 4.50 specification, section 5.1.
#include <cctype>
#include <stdexcept>

#include "codegen/glsl_subset.h"

namespace wg::glsl_subset {
namespace {

struct SubsetToken {
  enum class Kind { Ident, Number, Punct, End };
  Kind kind = Kind::End;
  std::string text;
  int line = 1;
};

// Longest first, so "<<=" wins over "<<" and "<".
constexpr std::string_view kSubsetPuncts[] = {"<<=", ">>=", "++", "--", "+=", "-=", "*=", "/=", "%=", "&=", "|=",
                                              "^=",  "==",  "!=", "<=", ">=", "&&", "||", "^^", "<<", ">>"};

std::vector<SubsetToken> tokenizeSubset(std::string_view s) {
  std::vector<SubsetToken> out;
  int line = 1;
  size_t i = 0;
  while (i < s.size()) {
    char c = s[i];
    if (c == '\n') { ++line; ++i; continue; }
    if (std::isspace(static_cast<unsigned char>(c))) { ++i; continue; }
    if (s.compare(i, 2, "//") == 0) {
      while (i < s.size() && s[i] != '\n') ++i;
      continue;
    }
    if (s.compare(i, 2, "/*") == 0) {
      size_t end = s.find("*/", i + 2);
      if (end == std::string_view::npos) throw std::logic_error("GLSL subset: unterminated comment");
      for (size_t k = i; k < end; ++k) line += s[k] == '\n';
      i = end + 2;
      continue;
    }
    if (c == '#') throw std::logic_error("GLSL subset: preprocessor line at line " + std::to_string(line));
    SubsetToken t;
    t.line = line;
    size_t start = i;
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      while (i < s.size() && (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '_')) ++i;
      t.kind = SubsetToken::Kind::Ident;
    } else if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
      while (i < s.size()) {
        char d = s[i];
        bool exponentSign = (d == '+' || d == '-') && (s[i - 1] == 'e' || s[i - 1] == 'E');
        if (std::isalnum(static_cast<unsigned char>(d)) || d == '.' || exponentSign) ++i;
        else break;
      }
      t.kind = SubsetToken::Kind::Number;
    } else {
      t.kind = SubsetToken::Kind::Punct;
      size_t len = 1;
      for (std::string_view p : kSubsetPuncts)
        if (s.compare(i, p.size(), p) == 0) { len = p.size(); break; }
      i += len;
    }
    t.text = std::string(s.substr(start, i - start));
    out.push_back(std::move(t));
  }
  out.push_back({SubsetToken::Kind::End, "", line});
  return out;
}

bool isSubsetTypeName(std::string_view n) {
  static constexpr std::string_view kTypes[] = {"void",  "float", "int",   "uint",  "bool",      "vec2",       "vec3",
                                                "vec4",  "ivec2", "ivec3", "ivec4", "uvec2",     "uvec3",      "uvec4",
                                                "bvec2", "bvec3", "bvec4", "mat2",  "mat3",      "mat4",       "sampler2D",
                                                "samplerCube"};
  for (auto t : kTypes)
    if (t == n) return true;
  return false;
}

bool isSubsetPrecision(std::string_view n) { return n == "highp" || n == "mediump" || n == "lowp"; }

class SubsetParser {
 public:
  explicit SubsetParser(std::string_view text) : tokens_(tokenizeSubset(text)) {}

  std::vector<Item> items() {
    std::vector<Item> out;
    while (!atEnd()) {
      Item item;
      bool isConst = accept("const");
      std::string type = typeName();
      std::string name = ident();
      if (isConst || peek("=")) {
        expect("=");
        item.constant = std::make_unique<GlobalConst>(GlobalConst{type, name, expression()});
        expect(";");
      } else {
        auto f = std::make_unique<Function>();
        f->returnType = type;
        f->name = name;
        expect("(");
        if (!accept(")")) {
          if (peek("void") && tokens_[pos_ + 1].text == ")") { ++pos_; }
          else {
            do {
              Param p;
              if (peek("in") || peek("out") || peek("inout")) p.qualifier = next().text;
              accept("const");
              p.type = typeName();
              p.name = ident();
              f->params.push_back(std::move(p));
            } while (accept(","));
          }
          expect(")");
        }
        expect("{");
        while (!accept("}")) f->body.push_back(statement());
        item.function = std::move(f);
      }
      out.push_back(std::move(item));
    }
    return out;
  }

  // One expression and nothing after it.
  ExprPtr wholeExpression() {
    ExprPtr e = expression();
    if (!atEnd()) fail("the end of the expression");
    return e;
  }

 private:
  StmtPtr statement() {
    auto s = std::make_unique<Stmt>();
    if (accept("{")) {
      s->kind = Stmt::Kind::Block;
      while (!accept("}")) s->body.push_back(statement());
    } else if (accept(";")) {
      s->kind = Stmt::Kind::Empty;
    } else if (accept("if")) {
      s->kind = Stmt::Kind::If;
      expect("(");
      s->expr = expression();
      expect(")");
      s->body.push_back(statement());
      s->body.push_back(accept("else") ? statement() : nullptr);
    } else if (accept("for")) {
      s->kind = Stmt::Kind::For;
      expect("(");
      s->body.push_back(statement());  // declaration, expression or empty; consumes ';'
      if (!peek(";")) s->expr = expression();
      expect(";");
      auto step = std::make_unique<Stmt>();
      if (!peek(")")) {
        step->kind = Stmt::Kind::Expression;
        step->expr = expression();
      }
      expect(")");
      s->body.push_back(std::move(step));
      s->body.push_back(statement());
    } else if (accept("while")) {
      s->kind = Stmt::Kind::While;
      expect("(");
      s->expr = expression();
      expect(")");
      s->body.push_back(statement());
    } else if (accept("return")) {
      s->kind = Stmt::Kind::Return;
      if (!peek(";")) s->expr = expression();
      expect(";");
    } else if (accept("break")) {
      s->kind = Stmt::Kind::Break;
      expect(";");
    } else if (accept("continue")) {
      s->kind = Stmt::Kind::Continue;
      expect(";");
    } else if (accept("discard")) {
      s->kind = Stmt::Kind::Discard;
      expect(";");
    } else if (peek("const") || startsDeclaration()) {
      s->kind = Stmt::Kind::Declare;
      s->isConst = accept("const");
      s->type = typeName();
      do {
        Declarator d;
        d.name = ident();
        if (peek("[")) fail("an array declaration");
        if (accept("=")) d.init = assignment();
        s->declared.push_back(std::move(d));
      } while (accept(","));
      expect(";");
    } else {
      s->kind = Stmt::Kind::Expression;
      s->expr = expression();
      expect(";");
    }
    return s;
  }

  bool startsDeclaration() const {
    const SubsetToken& t = tokens_[pos_];
    if (t.kind != SubsetToken::Kind::Ident) return false;
    if (isSubsetPrecision(t.text)) return true;
    return isSubsetTypeName(t.text) && tokens_[pos_ + 1].kind == SubsetToken::Kind::Ident;
  }

  // expression: assignment (',' assignment)* — the comma operator is outside the subset.
  ExprPtr expression() { return assignment(); }

  ExprPtr assignment() {
    ExprPtr lhs = ternary();
    static constexpr std::string_view kAssign[] = {"=", "+=", "-=", "*=", "/=", "%=", "<<=", ">>=", "&=", "|=", "^="};
    for (auto op : kAssign)
      if (peek(op)) {
        ++pos_;
        auto e = node(Expr::Kind::Assign, std::string(op));
        e->args.push_back(std::move(lhs));
        e->args.push_back(assignment());
        return e;
      }
    return lhs;
  }

  ExprPtr ternary() {
    ExprPtr c = binary(0);
    if (!accept("?")) return c;
    auto e = node(Expr::Kind::Ternary, "?:");
    e->args.push_back(std::move(c));
    e->args.push_back(assignment());
    expect(":");
    e->args.push_back(assignment());
    return e;
  }

  // Binary levels, loosest first.
  ExprPtr binary(size_t level) {
    static const std::vector<std::vector<std::string_view>> kLevels = {
        {"||"}, {"^^"}, {"&&"}, {"|"}, {"^"}, {"&"}, {"==", "!="}, {"<", ">", "<=", ">="}, {"<<", ">>"}, {"+", "-"},
        {"*", "/", "%"}};
    if (level == kLevels.size()) return unary();
    ExprPtr lhs = binary(level + 1);
    for (;;) {
      std::string_view found;
      for (auto op : kLevels[level])
        if (peek(op)) found = op;
      if (found.empty()) return lhs;
      ++pos_;
      auto e = node(Expr::Kind::Binary, std::string(found));
      e->args.push_back(std::move(lhs));
      e->args.push_back(binary(level + 1));
      lhs = std::move(e);
    }
  }

  ExprPtr unary() {
    static constexpr std::string_view kUnary[] = {"-", "+", "!", "~", "++", "--"};
    for (auto op : kUnary)
      if (peek(op)) {
        ++pos_;
        auto e = node(Expr::Kind::Unary, std::string(op));
        e->args.push_back(unary());
        return e;
      }
    return postfix();
  }

  ExprPtr postfix() {
    ExprPtr e = primary();
    for (;;) {
      if (accept("(")) {
        if (e->kind != Expr::Kind::Name) fail("a call of something that is not a name");
        e->kind = Expr::Kind::Call;
        if (!accept(")")) {
          do e->args.push_back(assignment());
          while (accept(","));
          expect(")");
        }
      } else if (accept("[")) {
        auto i = node(Expr::Kind::Index, "[]");
        i->args.push_back(std::move(e));
        i->args.push_back(expression());
        expect("]");
        e = std::move(i);
      } else if (accept(".")) {
        auto m = node(Expr::Kind::Member, ident());
        m->args.push_back(std::move(e));
        e = std::move(m);
      } else if (peek("++") || peek("--")) {
        auto p = node(Expr::Kind::Postfix, next().text);
        p->args.push_back(std::move(e));
        e = std::move(p);
      } else {
        return e;
      }
    }
  }

  ExprPtr primary() {
    if (accept("(")) {
      ExprPtr e = expression();
      expect(")");
      return e;
    }
    const SubsetToken& t = tokens_[pos_];
    if (t.kind == SubsetToken::Kind::Number) return node(Expr::Kind::Literal, next().text);
    if (t.kind == SubsetToken::Kind::Ident) return node(Expr::Kind::Name, next().text);
    fail("an expression");
    return nullptr;
  }

  std::string typeName() {
    while (isSubsetPrecision(tokens_[pos_].text)) ++pos_;
    const SubsetToken& t = tokens_[pos_];
    if (t.kind != SubsetToken::Kind::Ident || !isSubsetTypeName(t.text)) fail("a type name");
    return next().text;
  }

  std::string ident() {
    if (tokens_[pos_].kind != SubsetToken::Kind::Ident) fail("an identifier");
    return next().text;
  }

  ExprPtr node(Expr::Kind k, std::string text) {
    auto e = std::make_unique<Expr>();
    e->kind = k;
    e->text = std::move(text);
    return e;
  }

  bool atEnd() const { return tokens_[pos_].kind == SubsetToken::Kind::End; }
  bool peek(std::string_view s) const {
    return tokens_[pos_].kind != SubsetToken::Kind::End && tokens_[pos_].kind != SubsetToken::Kind::Number &&
           tokens_[pos_].text == s;
  }
  bool accept(std::string_view s) {
    if (!peek(s)) return false;
    ++pos_;
    return true;
  }
  void expect(std::string_view s) {
    if (!accept(s)) fail("'" + std::string(s) + "'");
  }
  const SubsetToken& next() { return tokens_[pos_++]; }
  [[noreturn]] void fail(const std::string& wanted) const {
    const SubsetToken& t = tokens_[pos_];
    throw std::logic_error("GLSL subset: expected " + wanted + " at line " + std::to_string(t.line) + ", found '" +
                           t.text + "'");
  }

  std::vector<SubsetToken> tokens_;
  size_t pos_ = 0;
};

// The `//` lines at the top of an item's text (its documentation), before its first code.
std::vector<std::string> leadingCommentLines(std::string_view text) {
  std::vector<std::string> out;
  size_t i = 0;
  while (i < text.size()) {
    size_t end = text.find('\n', i);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(i, end - i);
    size_t first = line.find_first_not_of(" \t");
    if (first == std::string_view::npos) { i = end + 1; continue; }
    if (line.compare(first, 2, "//") != 0) break;
    out.emplace_back(line.substr(first));
    i = end + 1;
  }
  return out;
}

}  // namespace

std::vector<Item> parseItems(std::string_view text) {
  std::vector<Item> items = SubsetParser(text).items();
  if (!items.empty()) items.front().leadingComments = leadingCommentLines(text);
  return items;
}

ExprPtr parseExpression(std::string_view text) { return SubsetParser(text).wholeExpression(); }

}  // namespace wg::glsl_subset
