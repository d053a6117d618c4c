#pragma once
// The GLSL that watergraph itself writes — the function library (nodes/glsl/*.glsl) and the
// expressions the nodes emit — parsed into a small syntax tree, so the WGSL emitter
// (codegen/emit_wgsl.h) can print it in WGSL's terms with every type known. Only the subset
// our own code uses is accepted: functions, global constants, declarations, if, for, while,
// return, break, continue, expressions. No preprocessor, no structs, no arrays of values.
// A construct outside the subset throws std::logic_error naming it: the text is ours, so
// that is a bug in a node, found by the test that translates the whole library.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace wg::glsl_subset {

struct Expr;
using ExprPtr = std::unique_ptr<Expr>;

struct Expr {
  enum class Kind { Name, Literal, Unary, Postfix, Binary, Ternary, Call, Member, Index, Assign };
  Kind kind = Kind::Name;
  std::string text;  // Name: identifier; Literal: as written; operators: the operator; Call: callee; Member: field
  std::vector<ExprPtr> args;  // operands in order (Call: arguments; Member, Index: object first)
};

struct Stmt;
using StmtPtr = std::unique_ptr<Stmt>;

struct Declarator {
  std::string name;
  ExprPtr init;  // may be null
};

struct Stmt {
  enum class Kind { Block, Declare, Expression, If, For, While, Return, Break, Continue, Discard, Empty };
  Kind kind = Kind::Empty;
  std::string type;                  // Declare: the GLSL type name
  bool isConst = false;              // Declare: `const`
  std::vector<Declarator> declared;  // Declare
  ExprPtr expr;                      // Expression, Return (may be null), If/While/For condition
  std::vector<StmtPtr> body;         // Block; If: then, else (else may be null); For: init, step-as-Expression, body
};

struct Param {
  std::string type, name;
  std::string qualifier;  // "", "in", "out", "inout"
};

struct Function {
  std::string returnType, name;
  std::vector<Param> params;
  std::vector<StmtPtr> body;
};

struct GlobalConst {
  std::string type, name;
  ExprPtr value;
};

// One top-level item of the library: a function or a constant (exactly one is set).
struct Item {
  std::unique_ptr<Function> function;
  std::unique_ptr<GlobalConst> constant;
  std::vector<std::string> leadingComments;  // the `//` lines right above it, as written
};

// Parses the items of `text` (one library item, or a whole file). Throws std::logic_error.
std::vector<Item> parseItems(std::string_view text);
// Parses one expression (what the planner declares or assigns in a stage's main(): the
// plan holds the statements as values, codegen/shader_plan.h). Throws std::logic_error.
ExprPtr parseExpression(std::string_view text);

}  // namespace wg::glsl_subset
