#pragma once
// An expression node's declared inputs (its "inputs" option, {"name": "float" | "vecN"}),
// edited as a list instead of as JSON text: declare one, change its type, rename it, remove
// it. A rename carries its references along, as one undo step: the declared name, the
// node's input port of that name (what feeds it stays connected) and every place the formula
// reads it ("mix(a, b, t)" with t renamed to k: "mix(a, b, k)"; a swizzle ".t" and a call
// "t(...)" are not references and stay).
#include <string>

#include "core/graph_edit.h"
#include "core/registry.h"
#include "core/types.h"

namespace wg::editor {

// Each "" when applied (one undo step), else why it was refused, the graph unchanged.
std::string declareExpressionInput(GraphEditor& editor, const Registry& registry, const std::string& node,
                                   const std::string& name, Type type);
std::string retypeExpressionInput(GraphEditor& editor, const Registry& registry, const std::string& node,
                                  const std::string& name, Type type);
std::string renameExpressionInput(GraphEditor& editor, const Registry& registry, const std::string& node,
                                  const std::string& from, const std::string& to);
// The input goes, with whatever fed its port; the formula is left as written (compiling
// then names the reference that is left, with its column).
std::string removeExpressionInput(GraphEditor& editor, const Registry& registry, const std::string& node,
                                  const std::string& name);

// `formula` with each reference to `from` renamed `to`, or why not (it does not tokenize).
std::string renameFormulaReferences(const std::string& formula, const std::string& from, const std::string& to,
                                    std::string* renamed);

}  // namespace wg::editor
