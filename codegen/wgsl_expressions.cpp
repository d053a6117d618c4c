// GLSL-subset expressions as WGSL (codegen/wgsl_expressions.h). Every binary operation is
// parenthesised: WGSL refuses some mixes GLSL's precedence allows (a || b && c, a & b == c).
#include "codegen/wgsl_expressions.h"

#include "codegen/wgsl_translate.h"

#include <algorithm>
#include <stdexcept>

namespace wg::wgsl {

using glsl_subset::Expr;

namespace {

[[noreturn]] void wgslUnsupported(const std::string& what) { throw std::logic_error("GLSL subset: " + what + " has no WGSL form here"); }

bool isOneOfNames(const std::string& s, std::initializer_list<const char*> names) {
  for (const char* n : names)
    if (s == n) return true;
  return false;
}

// GLSL names of built-ins that WGSL spells alike and whose result has the first argument's type.
bool sameNameGeneric(const std::string& n) {
  return isOneOfNames(n, {"abs",  "sign",  "floor", "ceil", "fract", "sqrt",  "exp",       "exp2",  "log",   "log2",
                   "sin",  "cos",   "tan",   "asin", "acos",  "sinh",  "cosh",      "tanh",  "pow",   "min",
                   "max",  "clamp", "mix",   "step", "smoothstep", "normalize", "reflect", "refract", "trunc",
                   "fma",  "radians", "degrees", "fwidth", "round"});
}

// Functions whose scalar arguments GLSL widens to the vector beside them.
bool widensScalars(const std::string& n) { return isOneOfNames(n, {"min", "max", "clamp", "step", "smoothstep"}); }

}  // namespace

std::string splatTo(const Printed& p, int size) {
  if (size == 1 || p.type.size != 1 || p.type.isMatrix()) return p.text;
  return wgslTypeName(ValueType{p.type.base, size, 0}) + "(" + p.text + ")";
}

Printed ExpressionPrinter::expression(const Expr& e) {
  switch (e.kind) {
    case Expr::Kind::Name: return name(e);
    case Expr::Kind::Literal: return literal(e);
    case Expr::Kind::Unary: return unary(e);
    case Expr::Kind::Binary: return binary(e);
    case Expr::Kind::Call: return call(e);
    case Expr::Kind::Member: return member(e);
    case Expr::Kind::Index: return index(e);
    case Expr::Kind::Ternary: {
      Printed c = expression(*e.args[0]);
      Printed a = expression(*e.args[1]);
      Printed b = expression(*e.args[2]);
      if (a.type.isSampler()) wgslUnsupported("a ?: between samplers");
      // select(false_value, true_value, condition): both sides evaluated, as the library intends.
      return {"select(" + b.text + ", " + a.text + ", " + c.text + ")", a.type, "", ""};
    }
    case Expr::Kind::Postfix:
    case Expr::Kind::Assign: wgslUnsupported("an assignment inside an expression");
  }
  wgslUnsupported("an expression");
}

std::string ExpressionPrinter::converted(const Expr& e, const ValueType& want) {
  Printed p = expression(e);
  if (!(p.type == want)) throw std::logic_error("GLSL subset: a value of another type where " + wgslTypeName(want) + " is wanted: " + p.text);
  return p.text;
}

std::string ExpressionPrinter::expressionStatement(const Expr& e) {
  if (e.kind == Expr::Kind::Assign) {
    const Expr& lhs = *e.args[0];
    if (lhs.kind == Expr::Kind::Member && lhs.text.size() > 1) wgslUnsupported("an assignment to a multi-component swizzle");
    Printed l = expression(lhs);
    Printed r = expression(*e.args[1]);
    std::string op = e.text;
    if (op == "<<=" || op == ">>=") r.text = splatTo({r.type.base == 'u' ? r.text : wgslTypeName(withBase(r.type, 'u')) + "(" + r.text + ")", withBase(r.type, 'u'), "", ""}, l.type.size);
    else if (op == "&=" || op == "|=" || op == "^=") r.text = splatTo(r, l.type.size);
    return l.text + " " + op + " " + r.text;
  }
  if ((e.kind == Expr::Kind::Unary || e.kind == Expr::Kind::Postfix) && (e.text == "++" || e.text == "--"))
    return expression(*e.args[0]).text + e.text;
  if (e.kind == Expr::Kind::Call) {
    Printed p = call(e);
    return p.type.base == 'v' ? p.text : "_ = " + p.text;
  }
  wgslUnsupported("an expression statement that is not an assignment or a call");
}

Printed ExpressionPrinter::name(const Expr& e) {
  if (e.text == "true" || e.text == "false") return {e.text, {'b', 1, 0}, "", ""};
  auto s = lookup(e.text);
  if (!s) throw std::logic_error("GLSL subset: unknown name '" + e.text + "'");
  return {s->wgsl, s->type, s->texture, s->sampler};
}

Printed ExpressionPrinter::literal(const Expr& e) {
  std::string t = e.text;
  bool hex = t.size() > 1 && t[0] == '0' && (t[1] == 'x' || t[1] == 'X');
  if (!t.empty() && (t.back() == 'u' || t.back() == 'U')) {
    t.back() = 'u';
    return {t, {'u', 1, 0}, "", ""};
  }
  bool isFloat = !hex && t.find_first_of(".eE") != std::string::npos;
  if (!isFloat) return {t, {'i', 1, 0}, "", ""};
  if (t.back() == 'f' || t.back() == 'F') t.pop_back();
  if (t.front() == '.') t.insert(t.begin(), '0');
  size_t dot = t.find('.');
  if (dot != std::string::npos && (dot + 1 == t.size() || !std::isdigit(static_cast<unsigned char>(t[dot + 1])))) t.insert(dot + 1, "0");
  return {t, {'f', 1, 0}, "", ""};
}

Printed ExpressionPrinter::unary(const Expr& e) {
  if (e.text == "++" || e.text == "--") wgslUnsupported("++/-- inside an expression");
  Printed a = expression(*e.args[0]);
  if (e.text == "+") return a;
  // "- -x" would read as a decrement: the operand of a unary operator keeps its own parentheses.
  std::string operand = a.text.empty() || a.text[0] == '-' || a.text[0] == '!' || a.text[0] == '~' ? "(" + a.text + ")" : a.text;
  return {e.text + operand, a.type, "", ""};
}

Printed ExpressionPrinter::binary(const Expr& e) {
  Printed a = expression(*e.args[0]);
  bool logical = e.text == "&&" || e.text == "||";
  // The right side of && and || runs only sometimes: WGSL counts that as non-uniform flow.
  bool wasTainted = tainted_;
  if (logical) tainted_ = true;
  Printed b = expression(*e.args[1]);
  tainted_ = wasTainted;
  const std::string& op = e.text;
  auto wrap = [](const std::string& s) { return "(" + s + ")"; };
  if (logical) return {wrap(a.text + " " + op + " " + b.text), {'b', 1, 0}, "", ""};
  if (op == "^^") return {wrap(a.text + " != " + b.text), {'b', 1, 0}, "", ""};
  if (op == "==" || op == "!=") {
    std::string cmp = wrap(a.text + " " + op + " " + b.text);
    if (a.type.isVector()) cmp = (op == "==" ? "all" : "any") + cmp;
    return {cmp, {'b', 1, 0}, "", ""};
  }
  if (op == "<" || op == ">" || op == "<=" || op == ">=") return {wrap(a.text + " " + op + " " + b.text), {'b', 1, 0}, "", ""};
  if (op == "<<" || op == ">>") {
    ValueType countType = withBase(b.type, 'u');
    Printed count{b.type.base == 'u' ? b.text : wgslTypeName(countType) + "(" + b.text + ")", countType, "", ""};
    return {wrap(a.text + " " + op + " " + splatTo(count, a.type.size)), a.type, "", ""};
  }
  if (op == "&" || op == "|" || op == "^") {
    int size = std::max(a.type.size, b.type.size);
    return {wrap(splatTo(a, size) + " " + op + " " + splatTo(b, size)), a.type.size >= b.type.size ? a.type : b.type, "", ""};
  }
  // + - * / %: WGSL mixes a scalar with a vector as GLSL does; matrices by the rules of algebra.
  if (op == "%" && a.type.base == 'f') wgslUnsupported("% on floats");
  ValueType result;
  if (op == "*" && a.type.isMatrix() && b.type.isMatrix()) result = {'f', a.type.size, b.type.cols};
  else if (op == "*" && a.type.isMatrix() && b.type.isVector()) result = {'f', a.type.size, 0};
  else if (op == "*" && a.type.isVector() && b.type.isMatrix()) result = {'f', b.type.cols, 0};
  else if (a.type.isMatrix()) result = a.type;
  else if (b.type.isMatrix()) result = b.type;
  else result = a.type.size >= b.type.size ? a.type : b.type;
  return {wrap(a.text + " " + op + " " + b.text), result, "", ""};
}

Printed ExpressionPrinter::member(const Expr& e) {
  Printed o = expression(*e.args[0]);
  if (!o.type.isVector() && !o.type.isScalar()) wgslUnsupported("a field of a " + wgslTypeName(o.type));
  std::string sw;
  for (char c : e.text) {
    switch (c) {
      case 'x': case 'r': case 's': sw += 'x'; break;
      case 'y': case 'g': case 't': sw += 'y'; break;
      case 'z': case 'b': case 'p': sw += 'z'; break;
      case 'w': case 'a': case 'q': sw += 'w'; break;
      default: wgslUnsupported("the swizzle ." + e.text);
    }
  }
  return {o.text + "." + sw, {o.type.base, static_cast<int>(sw.size()), 0}, "", ""};
}

Printed ExpressionPrinter::index(const Expr& e) {
  Printed o = expression(*e.args[0]);
  Printed i = expression(*e.args[1]);
  ValueType t = o.type.isMatrix() ? ValueType{o.type.base, o.type.size, 0} : ValueType{o.type.base, 1, 0};
  return {o.text + "[" + i.text + "]", t, "", ""};
}

Printed ExpressionPrinter::call(const Expr& e) {
  std::vector<Printed> args;
  for (const auto& a : e.args) args.push_back(expression(*a));
  const std::string& n = e.text;
  if (n == "texture" || n == "textureLod" || n == "texelFetch" || n == "textureSize") return texture(n, std::move(args));
  if (auto c = callee(n)) {
    // A function sampling with an implicit LOD has a second form sampling level 0 (NAME_lod0):
    // the vertex stage's, and the one called where control flow may have diverged.
    bool lod0 = c->samples && (vertexStage() || tainted_);
    if (c->samples && !tainted_) noteImplicitSample();
    std::string text = c->wgslName + (lod0 ? kLod0Suffix : "") + "(";
    for (size_t i = 0; i < args.size(); ++i) {
      if (i) text += ", ";
      text += args[i].type.isSampler() ? args[i].texture + ", " + args[i].sampler : args[i].text;
    }
    return {text + ")", c->result, "", ""};
  }
  bool isType = false;
  ValueType type;
  try {
    type = glslType(n);
    isType = type.base != 'v' && !type.isSampler();
  } catch (const std::logic_error&) {
  }
  if (isType) return constructor(type, std::move(args));
  return builtin(n, std::move(args));
}

Printed ExpressionPrinter::constructor(const ValueType& type, std::vector<Printed> args) {
  std::string name = wgslTypeName(type);
  if (type.isMatrix() && args.size() == 1 && args[0].type.isScalar()) {
    // mat3(s): s on the diagonal, zeros elsewhere.
    std::string entries;
    for (int c = 0; c < type.cols; ++c)
      for (int r = 0; r < type.size; ++r) entries += std::string(c || r ? ", " : "") + (c == r ? args[0].text : "0.0");
    return {name + "(" + entries + ")", type, "", ""};
  }
  if (type.isMatrix()) {
    // mat3(m4): the upper-left 3x3, which WGSL has no constructor for.
    if (args.size() == 1 && args[0].type.isMatrix()) {
      std::string cols;
      std::string sw = std::string("xyzw").substr(0, static_cast<size_t>(type.size));
      for (int c = 0; c < type.cols; ++c) cols += (c ? ", " : "") + args[0].text + "[" + std::to_string(c) + "]." + sw;
      return {name + "(" + cols + ")", type, "", ""};
    }
    if (args.size() != static_cast<size_t>(type.cols) && args.size() != static_cast<size_t>(type.cols * type.size))
      wgslUnsupported("a matrix constructor of " + std::to_string(args.size()) + " arguments");
  }
  if (args.size() == 1) {
    const Printed& a = args[0];
    if (type.isScalar()) return {a.type == type ? a.text : name + "(" + a.text + ")", type, "", ""};
    // vec3(v4): GLSL drops the last components; WGSL wants the size to match.
    if (a.type.isVector() && a.type.size > type.size)
      return {name + "(" + a.text + "." + std::string("xyzw").substr(0, static_cast<size_t>(type.size)) + ")", type, "", ""};
    // vec3(i): a splat of another scalar type converts first.
    if (a.type.isScalar() && a.type.base != type.base)
      return {name + "(" + wgslTypeName(ValueType{type.base, 1, 0}) + "(" + a.text + "))", type, "", ""};
    return {name + "(" + a.text + ")", type, "", ""};
  }
  std::string text = name + "(";
  for (size_t i = 0; i < args.size(); ++i) {
    const Printed& a = args[i];
    std::string piece = a.text;
    if (!type.isMatrix() && a.type.base != type.base) piece = wgslTypeName(withBase(a.type, type.base)) + "(" + a.text + ")";
    text += (i ? ", " : "") + piece;
  }
  return {text + ")", type, "", ""};
}

Printed ExpressionPrinter::builtin(const std::string& n, std::vector<Printed> args) {
  auto list = [&](size_t from = 0) {
    std::string s;
    for (size_t i = from; i < args.size(); ++i) s += (i > from ? ", " : "") + args[i].text;
    return s;
  };
  if (args.empty()) wgslUnsupported("the call " + n + "()");
  ValueType first = args[0].type;
  ValueType scalarOfFirst{first.base, 1, 0};
  if (widensScalars(n)) {
    int size = 1;
    for (const auto& a : args) size = std::max(size, a.type.size);
    for (auto& a : args) {
      a.text = splatTo(a, size);
      a.type.size = size;
    }
    return {n + "(" + list() + ")", args.back().type, "", ""};
  }
  // mix(a, b, bvec): GLSL's per-component choice, which is WGSL's select(a, b, condition).
  if (n == "mix" && args.size() == 3 && args[2].type.base == 'b') return {"select(" + list() + ")", first, "", ""};
  if (n == "mix") return {"mix(" + list() + ")", first.size >= args[1].type.size ? first : args[1].type, "", ""};
  if (sameNameGeneric(n)) return {n + "(" + list() + ")", first, "", ""};
  if (n == "inversesqrt") return {"inverseSqrt(" + list() + ")", first, "", ""};
  if (n == "faceforward") return {"faceForward(" + list() + ")", first, "", ""};
  if (n == "atan") return {(args.size() == 2 ? "atan2(" : "atan(") + list() + ")", first, "", ""};
  if (n == "roundEven") return {"round(" + list() + ")", first, "", ""};
  if (n == "dFdx" || n == "dFdy") {
    if (tainted_ || vertexStage()) wgslUnsupported(n + " under non-uniform control flow or in the vertex stage");
    noteImplicitSample();
    return {(n == "dFdx" ? "dpdx(" : "dpdy(") + list() + ")", first, "", ""};
  }
  if (n == "length" || n == "distance" || n == "dot" || n == "determinant") return {n + "(" + list() + ")", scalarOfFirst, "", ""};
  if (n == "cross") return {"cross(" + list() + ")", first, "", ""};
  if (n == "transpose") return {"transpose(" + list() + ")", {first.base, first.cols, first.size}, "", ""};
  if (n == "any" || n == "all") return {n + "(" + list() + ")", {'b', 1, 0}, "", ""};
  if (n == "not") return {"!(" + list() + ")", first, "", ""};
  if (n == "mod") {
    int size = std::max(first.size, args[1].type.size);
    ValueType t{'f', size, 0};
    if (first.base != 'f') wgslUnsupported("mod of integers");
    useModHelper(t);
    return {modHelperName(t) + "(" + splatTo(args[0], size) + ", " + splatTo(args[1], size) + ")", t, "", ""};
  }
  static const std::pair<const char*, const char*> kComparisons[] = {
      {"lessThan", "<"}, {"lessThanEqual", "<="}, {"greaterThan", ">"}, {"greaterThanEqual", ">="}, {"equal", "=="}, {"notEqual", "!="}};
  for (auto [glsl, op] : kComparisons)
    if (n == glsl) return {"(" + args[0].text + " " + op + " " + args[1].text + ")", withBase(first, 'b'), "", ""};
  if (n == "floatBitsToUint" || n == "floatBitsToInt" || n == "uintBitsToFloat" || n == "intBitsToFloat") {
    char base = n == "floatBitsToUint" ? 'u' : n == "floatBitsToInt" ? 'i' : 'f';
    ValueType t = withBase(first, base);
    return {"bitcast<" + wgslTypeName(t) + ">(" + list() + ")", t, "", ""};
  }
  wgslUnsupported("the built-in " + n + "()");
}

Printed ExpressionPrinter::texture(const std::string& n, std::vector<Printed> args) {
  if (args.empty() || !args[0].type.isSampler()) wgslUnsupported(n + " of something that is not a sampler");
  const Printed& s = args[0];
  ValueType vec4{'f', 4, 0};
  if (n == "textureSize") return {"vec2<i32>(textureDimensions(" + s.texture + ", " + args[1].text + "))", {'i', 2, 0}, "", ""};
  if (n == "texelFetch") return {"textureLoad(" + s.texture + ", " + args[1].text + ", " + args[2].text + ")", vec4, "", ""};
  std::string head = s.texture + ", " + s.sampler + ", " + args[1].text;
  if (n == "textureLod") return {"textureSampleLevel(" + head + ", " + args[2].text + ")", vec4, "", ""};
  if (args.size() != 2) wgslUnsupported("texture() with a bias");
  // Its fragment form is textureSample exactly when control flow is still uniform here.
  if (!tainted_) noteImplicitSample();
  // GLSL's vertex stage samples level 0; WGSL needs uniform control flow for an implicit LOD.
  if (vertexStage() || tainted_) return {"textureSampleLevel(" + head + ", 0.0)", vec4, "", ""};
  return {"textureSample(" + head + ")", vec4, "", ""};
}

}  // namespace wg::wgsl
