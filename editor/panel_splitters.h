#pragma once
// The splitters between the editor's panels: thin handles over the borders that drag the
// PanelLayout's fractions (editor/panel_layout.h). Drawn after the panels, above them.
#include "editor/panel_layout.h"

namespace wg::editor {

// True in the frame a drag ends (the layout then has its new value to remember).
bool drawPanelSplitters(PanelLayout& layout, float windowWidth, float windowHeight);

}  // namespace wg::editor
