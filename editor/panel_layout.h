#pragma once
// How the window is split between the panels, and what else the editor remembers: the left column's width (preview over node
// canvas) and, in each column, where the upper panel ends. Dragged with the splitters
// between the panels and remembered across runs in a small settings file.
#include <optional>
#include <string>
#include <vector>

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

// What the editor remembers between runs: the panel sizes and the graphs opened last.
struct EditorSettings {
  PanelLayout panels;
  std::vector<std::string> recent;  // absolute paths, the last opened first

  static constexpr size_t kRecentFiles = 8;
  // `path` to the front of `recent` (once), the list cut to kRecentFiles.
  void opened(const std::string& path);
};

// The settings file when none is named: $XDG_CONFIG_HOME/watergraph/editor.json, else
// ~/.config/watergraph/editor.json; "" when neither variable is set.
std::string defaultSettingsPath();
// The settings in the file; the defaults for what is missing, or for a file that is not a
// settings file.
EditorSettings loadEditorSettings(const std::string& path);
// Writes them (creating the folder); "" or why not.
std::string saveEditorSettings(const std::string& path, const EditorSettings& settings);
// The layout alone (tests, and a file holding nothing else): none when there is no "panels".
std::optional<PanelLayout> loadPanelLayout(const std::string& path);

}  // namespace wg::editor
