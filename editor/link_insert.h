#pragma once
// A new node dropped into an existing link (Blender's auto-insert on a link, Unity's
// "insert node"): right-click on a link, pick the type, and the node is added at that point,
// fed by the link's source and feeding the link's input, as one undo step. Wiring a node
// between two others is then one right-click and one choice.
#include <array>
#include <string>

#include "core/graph_edit.h"
#include "core/registry.h"

namespace wg::editor {

// Adds a node of `type` at `position` into the link that feeds `target` (a node input, or an
// output slot with an empty node). The link's source goes to the new node's first input of
// the source's fixed type, else its first generic input, else its first input; the new
// node's first output feeds `target`. Refused (graph unchanged) when `target` is not fed by
// a node output, or the type has no input or no output. The id used goes to *usedId.
std::string insertNodeOnLink(GraphEditor& editor, const Registry& registry, const std::string& type, const InputTarget& target,
                             std::array<double, 2> position, std::string* usedId = nullptr);

}  // namespace wg::editor
