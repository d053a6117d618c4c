#pragma once
// How the window is split between the panels: the left column's width (preview over node
// canvas) and, in each column, where the upper panel ends. Dragged with the splitters
// between the panels and remembered across runs in a small settings file.
#include <optional>
#include <string>

namespace wg::editor {

struct PanelLayout {
  // Fractions of the window. The defaults give the canvas most of the window: at 1600x900,
  // 1024x495 pixels (it was 985x340).
  float leftWidth = 0.64f;       // the preview and canvas column
  float previewHeight = 0.45f;   // the preview, above the canvas
  float inspectorHeight = 0.68f; // the inspector, above the error list

  // Each fraction kept where every panel stays usable (0.15 .. 0.85).
  void clampToUsable();
  bool operator==(const PanelLayout&) const = default;
};

// The settings file when none is named: $XDG_CONFIG_HOME/watergraph/editor.json, else
// ~/.config/watergraph/editor.json; "" when neither variable is set.
std::string defaultSettingsPath();
// The layout in the file; none when it is missing or not a settings file (the defaults then).
std::optional<PanelLayout> loadPanelLayout(const std::string& path);
// Writes the layout (creating the folder); "" or why not.
std::string savePanelLayout(const std::string& path, const PanelLayout& layout);

}  // namespace wg::editor
