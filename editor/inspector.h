#pragma once
// The inspector panels: the graph's parameters (sliders within min/max, colour pickers for
// hint "color") and the selected node (its inputs as constants, parameters or links, and
// its options: an expression's inputs as a list, a texture from a picker; for a subgraph
// instance, its file). Every change goes through the
// GraphEditor, so it can be undone.
#include <string>

#include "core/graph_edit.h"
#include "core/registry.h"

namespace wg::editor {

void drawParameterInspector(GraphEditor& editor);
// True when the user asked to open the selected instance's subgraph. `graphDir` is the
// edited file's folder (texture paths are relative to it).
bool drawNodeInspector(GraphEditor& editor, const Registry& registry, const std::string& nodeId, const std::string& graphDir);

}  // namespace wg::editor
