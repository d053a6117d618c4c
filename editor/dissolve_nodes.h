#pragma once
// Delete with reconnection (Blender's "Delete with Reconnect", Ctrl+X there; Ctrl+Delete
// here, where Ctrl+X is cut): the selected nodes go, and whatever read a pass-through
// output of theirs reads, instead, what fed the matching input. A node's output passes
// through one input when that is unambiguous:
// - a fixed-type output (vec3) and exactly one linked input of that fixed type;
// - a generic output (float to vec4, its type follows its inputs) and exactly one linked
//   generic input, while no other generic input holds a written vector constant (which
//   would have widened the output).
// "Linked" means fed by a node output or a parameter; a constant is not carried over.
// Otherwise the readers are disconnected, as plain Delete does. Chains of removed nodes
// are followed to the first source that stays. One undo step.
#include <optional>
#include <string>
#include <vector>

#include "core/graph.h"
#include "core/graph_edit.h"
#include "core/registry.h"

namespace wg::editor {

// Where a reader of output `port` of node `id` is reconnected to when `id` is dissolved:
// the source of the pass-through input, or nothing when there is none.
std::optional<InputSource> passThroughSource(const Graph& graph, const Registry& registry, const std::string& id,
                                             const std::string& port);

// Removes `ids` reconnecting their pass-throughs; "" on success, else why not (the graph
// unchanged). `*reconnected` (when given) counts the readers that were reconnected.
std::string dissolveNodes(GraphEditor& editor, const Registry& registry, const std::vector<std::string>& ids,
                          int* reconnected = nullptr);

}  // namespace wg::editor
