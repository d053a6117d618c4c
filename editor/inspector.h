#pragma once
// The inspector panels: the graph's parameters (sliders within min/max, colour pickers for
// hint "color") and the selected node (its inputs as constants, parameters or links, and
// its options; for a subgraph instance, its file). Every change goes through the
// GraphEditor, so it can be undone.
#include <string>

#include "core/graph_edit.h"
#include "core/registry.h"

namespace wg::editor {

void drawParameterInspector(GraphEditor& editor);
// True when the user asked to open the selected instance's subgraph.
bool drawNodeInspector(GraphEditor& editor, const Registry& registry, const std::string& nodeId);

}  // namespace wg::editor
