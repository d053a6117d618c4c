#pragma once
// The blackboard: the inspector's controls that change what parameters and presets the
// graph has (the sliders change their values): add a parameter, and per parameter a
// right-click menu to rename it (references follow), move it up or down, or delete it
// (refused, naming what reads it); save the current values as a preset, rename or delete
// one. A refused name is shown in place, in red, and nothing changes.
#include <string>

#include "core/graph_edit.h"

namespace wg::editor {

// Above the parameter sliders: "+ parameter" and the preset controls.
void drawBlackboardControls(GraphEditor& editor);
// Right after parameter `name`'s slider: its right-click menu.
void drawParameterMenu(GraphEditor& editor, const std::string& name);

}  // namespace wg::editor
