#include "core/texture_check.h"

#include <algorithm>
#include <filesystem>

#include "core/interface_tables.h"

namespace wg {

const std::vector<std::string>& builtinTextureNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& row : builtinTextureTable()) n.emplace_back(row.name);
    return n;
  }();
  return names;
}

std::string checkTextureSource(std::string_view source, const std::string& graphDir) {
  if (source.rfind(kBuiltinTexturePrefix, 0) == 0) {
    std::string name(source.substr(kBuiltinTexturePrefix.size()));
    const auto& names = builtinTextureNames();
    if (std::find(names.begin(), names.end(), name) != names.end()) return "";
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "builtin:" : ", builtin:") + n;
    return "unknown built-in texture '" + std::string(source) + "' (" + list + ")";
  }
  std::filesystem::path rel(source);
  if (source.empty()) return "an empty texture path";
  if (rel.is_absolute()) return "texture path '" + std::string(source) + "' must be relative to the graph file";
  for (const auto& part : rel)
    if (part == "..") return "texture path '" + std::string(source) + "' leaves the graph's folder";
  if (rel.extension() != ".png") return "texture '" + std::string(source) + "' is not a .png file";
  std::filesystem::path full = std::filesystem::path(graphDir.empty() ? "." : graphDir) / rel;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(full, ec)) return "texture file '" + full.string() + "' does not exist";
  return "";
}

}  // namespace wg
