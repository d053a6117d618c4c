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

void EditorSettings::opened(const std::string& path) {
  std::error_code ec;
  std::string absolute = std::filesystem::absolute(path, ec).lexically_normal().string();
  if (ec) absolute = path;
  std::erase(recent, absolute);
  recent.insert(recent.begin(), absolute);
  if (recent.size() > kRecentFiles) recent.resize(kRecentFiles);
}

namespace {

std::optional<nlohmann::json> readSettingsJson(const std::string& path) {
  FileReadRule rule;
  rule.maxBytes = 64 * 1024;  // a few numbers and paths; anything larger is not ours
  FileReadFailure failure;
  auto file = readFileChecked(path, rule, &failure);
  if (!file) return std::nullopt;
  nlohmann::json doc = nlohmann::json::parse(file->bytes, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return std::nullopt;
  return doc;
}

std::optional<PanelLayout> panelsOf(const nlohmann::json& doc) {
  if (!doc.contains("panels") || !doc["panels"].is_object()) return std::nullopt;
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

}  // namespace

std::optional<PanelLayout> loadPanelLayout(const std::string& path) {
  auto doc = readSettingsJson(path);
  return doc ? panelsOf(*doc) : std::nullopt;
}

EditorSettings loadEditorSettings(const std::string& path) {
  EditorSettings settings;
  auto doc = readSettingsJson(path);
  if (!doc) return settings;
  if (auto panels = panelsOf(*doc)) settings.panels = *panels;
  if (doc->contains("recent") && (*doc)["recent"].is_array())
    for (const auto& r : (*doc)["recent"])
      if (r.is_string() && settings.recent.size() < EditorSettings::kRecentFiles) settings.recent.push_back(r.get<std::string>());
  return settings;
}

std::string saveEditorSettings(const std::string& path, const EditorSettings& settings) {
  // Written by hand for the shortest decimals (nlohmann would widen the floats).
  auto num = [](float f) { return formatNumber(std::round(static_cast<double>(f) * 1000) / 1000); };
  const PanelLayout& layout = settings.panels;
  std::string text = "{\n  \"panels\": {\"left_width\": " + num(layout.leftWidth) + ", \"preview_height\": " +
                     num(layout.previewHeight) + ", \"inspector_height\": " + num(layout.inspectorHeight) + "},\n  \"recent\": [";
  for (size_t i = 0; i < settings.recent.size(); ++i) text += (i ? ", " : "") + nlohmann::json(settings.recent[i]).dump();
  text += "]\n}\n";
  Diagnostics d;
  if (!writeFileAtomically(path, text, d)) return d.all().empty() ? "cannot write " + path : formatText(d.all().front());
  return "";
}

}  // namespace wg::editor
