#pragma once
// An `expression` node's typed formula as ops of the math nodes, appended to a Program:
// so the passes (pruning, folding, CSE, value facts, stages), the emitter's guarded
// library functions and the CPU backend's double references treat a formula exactly as if
// its nodes had been wired by hand.
#include <functional>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include "core/expression_ast.h"
#include "core/expression_lexer.h"
#include "core/program.h"
#include "core/registry.h"

namespace wg::expr {

struct LoweredFormula {
  ValueRef value;  // the formula's result: an op's output, a constant or an input's source
  Type type = Type::Invalid;
};

struct LoweringContext {
  const Registry* registry = nullptr;
  std::string nodeId;                        // the expression node: every op is named after it
  std::map<std::string, ValueRef> inputs;    // each declared input's source
  std::function<SourceRef(Span)> where;      // a span of the formula as a place in the file
};

// Appends the ops computing `ast` (typed by typeFormula as `types`) to `program`.
std::variant<LoweredFormula, FormulaError> lowerFormula(const Ast& ast, const std::vector<Type>& types,
                                                        const LoweringContext& context, Program& program);

}  // namespace wg::expr
