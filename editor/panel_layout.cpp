#include "editor/panel_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "codegen/output_files.h"
#include "core/file_read.h"
#include "core/number_format.h"

namespace wg::editor {

void PanelLayout::clampToUsable() {
  for (float* f : {&leftWidth, &previewHeight, &inspectorHeight})
    *f = std::isfinite(*f) ? std::clamp(*f, 0.15f, 0.85f) : 0.5f;
}

std::string defaultSettingsPath() {
  const char* xdg = std::getenv("XDG_CONFIG_HOME");
  if (xdg && *xdg) return (std::filesystem::path(xdg) / "watergraph" / "editor.json").string();
  const char* home = std::getenv("HOME");
  if (home && *home) return (std::filesystem::path(home) / ".config" / "watergraph" / "editor.json").string();
  return "";
}

std::optional<PanelLayout> loadPanelLayout(const std::string& path) {
  FileReadRule rule;
  rule.maxBytes = 64 * 1024;  // a few numbers; anything larger is not ours
  FileReadFailure failure;
  auto file = readFileChecked(path, rule, &failure);
  if (!file) return std::nullopt;
  nlohmann::json doc = nlohmann::json::parse(file->bytes, nullptr, false);
  if (doc.is_discarded() || !doc.is_object() || !doc.contains("panels") || !doc["panels"].is_object()) return std::nullopt;
  const auto& p = doc["panels"];
  PanelLayout layout;
  auto read = [&](const char* key, float* to) {
    if (p.contains(key) && p[key].is_number()) *to = p[key].get<float>();
  };
  read("left_width", &layout.leftWidth);
  read("preview_height", &layout.previewHeight);
  read("inspector_height", &layout.inspectorHeight);
  layout.clampToUsable();
  return layout;
}

std::string savePanelLayout(const std::string& path, const PanelLayout& layout) {
  // Written by hand for the shortest decimals (nlohmann would widen the floats).
  auto num = [](float f) { return formatNumber(std::round(static_cast<double>(f) * 1000) / 1000); };
  std::string text = "{\n  \"panels\": {\"left_width\": " + num(layout.leftWidth) + ", \"preview_height\": " +
                     num(layout.previewHeight) + ", \"inspector_height\": " + num(layout.inspectorHeight) + "}\n}\n";
  Diagnostics d;
  if (!writeFileAtomically(path, text, d)) return d.all().empty() ? "cannot write " + path : formatText(d.all().front());
  return "";
}

}  // namespace wg::editor
