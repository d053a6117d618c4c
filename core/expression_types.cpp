#include "core/expression_types.h"

#include <algorithm>

#include "core/suggest.h"

namespace wg::expr {
namespace {

std::string quoted(Type t) { return "'" + std::string(typeName(t)) + "'"; }

bool isVector(Type t) { return t == Type::Vec2 || t == Type::Vec3 || t == Type::Vec4; }

// The component index of swizzle letter c in its set (xyzw, rgba, stpq), and the set.
std::optional<std::pair<int, int>> swizzleLetter(char c) {
  static const std::string_view kSets[] = {"xyzw", "rgba", "stpq"};
  for (int set = 0; set < 3; ++set) {
    std::size_t i = kSets[set].find(c);
    if (i != std::string_view::npos) return std::pair<int, int>{static_cast<int>(i), set};
  }
  return std::nullopt;
}

class Typer {
 public:
  Typer(const Ast& ast, const FormulaInputs& inputs) : ast_(ast), inputs_(inputs) {}

  std::vector<Type> run() {
    types_.assign(ast_.nodes.size(), Type::Invalid);
    for (std::size_t i = 0; i < ast_.nodes.size(); ++i) types_[i] = typeOf(ast_.nodes[i]);
    Type result = types_[static_cast<std::size_t>(ast_.root)];
    if (result == Type::Bool)
      fail(ast_.nodes[static_cast<std::size_t>(ast_.root)].span,
           "the formula is a comparison (a bool); a node's output is a float or vector: choose values with '?:'");
    return types_;
  }

  struct Stop {
    FormulaError error;
  };

 private:
  [[noreturn]] static void fail(Span span, std::string message) { throw Stop{{span, std::move(message)}}; }

  const Node& operand(const Node& n, std::size_t k) const {
    return ast_.nodes[static_cast<std::size_t>(n.operands[k])];
  }
  Type typeOfOperand(const Node& n, std::size_t k) const { return types_[static_cast<std::size_t>(n.operands[k])]; }

  // A value operand: float or vector, not a comparison.
  Type value(const Node& n, std::size_t k, const std::string& where) const {
    Type t = typeOfOperand(n, k);
    if (t == Type::Bool)
      fail(operand(n, k).span, "a comparison (a bool) cannot be " + where + "; use it as the condition of '?:'");
    return t;
  }

  Type typeOf(const Node& n) {
    switch (n.kind) {
      case NodeKind::Number: return Type::Float;
      case NodeKind::Name: return input(n);
      case NodeKind::Negate: return value(n, 0, "negated");
      case NodeKind::Binary: return generic(n, "an operand of '" + n.text + "'", "'" + n.text + "'");
      case NodeKind::Compare: {
        for (std::size_t k = 0; k < 2; ++k)
          if (value(n, k, "compared") != Type::Float)
            fail(operand(n, k).span, "'" + n.text + "' compares floats, not " + quoted(typeOfOperand(n, k)) +
                                         " (compare components, such as v.x)");
        return Type::Bool;
      }
      case NodeKind::Select: {
        if (typeOfOperand(n, 0) != Type::Bool)
          fail(operand(n, 0).span, "the condition of '?:' must be a comparison such as 'a < b', not a " +
                                       quoted(typeOfOperand(n, 0)));
        Type a = value(n, 1, "a choice of '?:'"), b = value(n, 2, "a choice of '?:'");
        if (a != b)
          fail(n.span, "the two choices of '?:' have types " + quoted(a) + " and " + quoted(b) + "; they must be the same");
        return a;
      }
      case NodeKind::Swizzle: return swizzle(n);
      case NodeKind::Call: return call(n);
    }
    return Type::Invalid;
  }

  Type input(const Node& n) {
    for (const auto& [name, type] : inputs_)
      if (name == n.text) return type;
    for (const auto& f : formulaFunctions())
      if (f.name == n.text) fail(n.span, "'" + n.text + "' is a function: call it, as in " + n.text + "(...)");
    std::vector<std::string> names;
    for (const auto& in : inputs_) names.push_back(in.first);
    NameSuggester suggest(names);
    std::string message = "unknown input '" + n.text + "'" + suggest.didYouMean(n.text);
    if (inputs_.empty()) message += "; the node declares no inputs";
    fail(n.span, message);
  }

  // Operands each T or float, the vectors one T: the result T, or float when all are float.
  Type generic(const Node& n, const std::string& role, const std::string& what) {
    Type vector = Type::Float;
    for (std::size_t k = 0; k < n.operands.size(); ++k) {
      Type t = value(n, k, role);
      if (t == Type::Float) continue;
      if (vector != Type::Float && t != vector)
        fail(n.span, what + " mixes " + quoted(vector) + " and " + quoted(t) +
                         "; vectors must have the same size (a float goes with any)");
      vector = t;
    }
    return vector;
  }

  Type swizzle(const Node& n) {
    Type base = value(n, 0, "swizzled");
    if (!isVector(base)) fail(n.span, "a " + quoted(base) + " has no components to swizzle; '." + n.text + "' needs a vector");
    if (n.text.size() > 4) fail(n.span, "a swizzle picks at most 4 components, not " + std::to_string(n.text.size()));
    int set = -1;
    for (char c : n.text) {
      auto letter = swizzleLetter(c);
      if (!letter) fail(n.span, "'" + std::string(1, c) + "' is not a component: use x y z w, r g b a or s t p q");
      if (set >= 0 && letter->second != set) fail(n.span, "'." + n.text + "' mixes the sets xyzw, rgba and stpq");
      set = letter->second;
      if (letter->first >= componentCount(base))
        fail(n.span, "'" + std::string(1, c) + "' is past the end of a " + quoted(base));
    }
    return floatVector(static_cast<int>(n.text.size()));
  }

  Type constructor(const Node& n, Type type) {
    int want = componentCount(type), have = 0;
    for (std::size_t k = 0; k < n.operands.size(); ++k) have += componentCount(value(n, k, "a component"));
    if (n.operands.size() == 1 && typeOfOperand(n, 0) == Type::Float) return type;  // vec3(0.5): every component
    if (n.operands.empty() || have < want)
      fail(n.span, n.text + "(...) needs " + std::to_string(want) + " components, given " + std::to_string(have));
    // GLSL drops the last argument's surplus components, but only the last argument's.
    int before = have - componentCount(typeOfOperand(n, n.operands.size() - 1));
    if (before >= want)
      fail(operand(n, n.operands.size() - 1).span, n.text + "(...) needs " + std::to_string(want) +
                                                      " components; this argument is past them");
    return type;
  }

  Type call(const Node& n) {
    if (n.text == "vec2" || n.text == "vec3" || n.text == "vec4") return constructor(n, *parseType(n.text));
    const FormulaFunction* match = nullptr;
    std::vector<int> arities;
    for (const auto& f : formulaFunctions()) {
      if (f.name != n.text) continue;
      arities.push_back(f.arity);
      if (f.arity == static_cast<int>(n.operands.size())) match = &f;
    }
    if (arities.empty()) {
      std::vector<std::string> names = {"vec2", "vec3", "vec4"};
      for (const auto& f : formulaFunctions()) names.emplace_back(f.name);
      NameSuggester suggest(names);
      std::string message = "unknown function '" + n.text + "'" + suggest.didYouMean(n.text);
      for (const auto& in : inputs_)
        if (in.first == n.text) message = "'" + n.text + "' is an input, not a function";
      fail(n.span, message);
    }
    if (!match) {
      std::string counts;
      for (std::size_t i = 0; i < arities.size(); ++i)
        counts += (i ? " or " : "") + std::to_string(arities[i]);
      fail(n.span, "'" + n.text + "' takes " + counts + " argument" + (arities.back() == 1 ? "" : "s") + ", given " +
                       std::to_string(n.operands.size()));
    }
    std::string role = "an argument of '" + n.text + "'";
    switch (match->signature) {
      case Signature::Generic: return generic(n, role, "'" + n.text + "'");
      case Signature::ToFloat: generic(n, role, "'" + n.text + "'"); return Type::Float;
      case Signature::Cross:
        for (std::size_t k = 0; k < 2; ++k)
          if (value(n, k, role) != Type::Vec3)
            fail(operand(n, k).span, "'cross' takes two 'vec3', not " + quoted(typeOfOperand(n, k)));
        return Type::Vec3;
      case Signature::Refract: {
        if (value(n, 2, role) != Type::Float)
          fail(operand(n, 2).span, "the third argument of 'refract' (the ratio of indices) is a 'float', not " +
                                       quoted(typeOfOperand(n, 2)));
        Type i = value(n, 0, role), normal = value(n, 1, role);
        if (i != normal)
          fail(n.span, "'refract' takes two directions of one type, given " + quoted(i) + " and " + quoted(normal));
        return i;
      }
      case Signature::SameVectors: {
        Type first = value(n, 0, role);
        for (std::size_t k = 1; k < n.operands.size(); ++k)
          if (value(n, k, role) != first)
            fail(operand(n, k).span, "'" + n.text + "' takes arguments of one type: " + quoted(first) + " and " +
                                         quoted(typeOfOperand(n, k)));
        return first;
      }
    }
    return Type::Invalid;
  }

  const Ast& ast_;
  const FormulaInputs& inputs_;
  std::vector<Type> types_;
};

}  // namespace

const std::vector<FormulaFunction>& formulaFunctions() {
  using S = Signature;
  static const std::vector<FormulaFunction> table = {
      // One argument, component-wise.
      {"abs", 1, "abs", S::Generic}, {"sign", 1, "sign", S::Generic}, {"floor", 1, "floor", S::Generic},
      {"ceil", 1, "ceil", S::Generic}, {"round", 1, "round", S::Generic}, {"trunc", 1, "trunc", S::Generic},
      {"fract", 1, "fract", S::Generic}, {"exp", 1, "exp", S::Generic}, {"exp2", 1, "exp2", S::Generic},
      {"log", 1, "log", S::Generic}, {"log2", 1, "log2", S::Generic}, {"sqrt", 1, "sqrt", S::Generic},
      {"inversesqrt", 1, "inversesqrt", S::Generic}, {"sin", 1, "sin", S::Generic}, {"cos", 1, "cos", S::Generic},
      {"tan", 1, "tan", S::Generic}, {"asin", 1, "asin", S::Generic}, {"acos", 1, "acos", S::Generic},
      {"atan", 1, "atan", S::Generic}, {"sinh", 1, "sinh", S::Generic}, {"cosh", 1, "cosh", S::Generic},
      {"tanh", 1, "tanh", S::Generic}, {"normalize", 1, "normalize", S::Generic},
      // Two and three arguments, a float going with any vector.
      {"atan", 2, "atan2", S::Generic}, {"min", 2, "min", S::Generic}, {"max", 2, "max", S::Generic},
      {"mod", 2, "mod", S::Generic}, {"pow", 2, "pow", S::Generic}, {"step", 2, "step", S::Generic},
      {"mix", 3, "mix", S::Generic}, {"clamp", 3, "clamp", S::Generic}, {"smoothstep", 3, "smoothstep", S::Generic},
      // Geometry.
      {"length", 1, "length", S::ToFloat}, {"dot", 2, "dot", S::ToFloat}, {"distance", 2, "distance", S::ToFloat},
      {"cross", 2, "cross", S::Cross}, {"reflect", 2, "reflect", S::SameVectors},
      {"faceforward", 3, "faceforward", S::SameVectors}, {"refract", 3, "refract", S::Refract},
  };
  return table;
}

std::variant<std::vector<Type>, FormulaError> typeFormula(const Ast& ast, const FormulaInputs& inputs) {
  if (ast.root < 0 || ast.nodes.empty()) return FormulaError{{0, 0}, "the formula is empty"};
  try {
    return Typer(ast, inputs).run();
  } catch (const Typer::Stop& stop) {
    return stop.error;
  }
}

}  // namespace wg::expr
