#pragma once
// The syntax tree of an `expression` node's formula: a GLSL-like expression language of
// literals, names, + - * /, unary minus, comparisons, ?:, swizzles and calls (the built-in
// functions and the vecN constructors). No statements, loops or assignments.
// Nodes live in one vector and refer to their operands by index, so the tree is freed,
// copied and walked without recursion.
#include <cstddef>
#include <string>
#include <vector>

namespace wg::expr {

// A span of the formula's text, in bytes from its start.
struct Span {
  std::size_t offset = 0;
  std::size_t length = 0;
};

enum class NodeKind {
  Number,    // a literal: value
  Name,      // a declared input: text
  Negate,    // -operands[0]
  Binary,    // operands[0] text operands[1], text one of + - * /
  Compare,   // operands[0] text operands[1], text one of < <= > >= == !=
  Select,    // operands[0] ? operands[1] : operands[2]
  Call,      // text(operands...): a function or a vecN constructor
  Swizzle,   // operands[0].text, text one to four of xyzw, rgba or stpq
};

struct Node {
  NodeKind kind = NodeKind::Number;
  std::string text;
  double value = 0;
  std::vector<int> operands;
  Span span;  // the whole node's text (for a call, from its name to its ')')
};

struct Ast {
  std::vector<Node> nodes;  // every operand's index is lower than its user's
  int root = -1;
};

}  // namespace wg::expr
