#include "editor/error_list.h"

#include <filesystem>

namespace wg::editor {
namespace {

namespace fs = std::filesystem;

std::string shortPath(const std::string& file, const fs::path& folder) {
  if (file.empty() || folder.empty()) return file;
  fs::path rel = fs::path(file).lexically_normal().lexically_relative(folder);
  if (rel.empty() || *rel.begin() == "..") return file;
  return rel.generic_string();
}

}  // namespace

std::string errorListText(const Diagnostic& d, const std::string& folder) {
  fs::path dir = fs::path(folder).lexically_normal();
  Diagnostic shown = d;
  shown.where.file = shortPath(d.where.file, dir);
  for (auto& note : shown.locatedNotes) note.where.file = shortPath(note.where.file, dir);
  return formatText(shown);
}

std::string nodeToSelect(const Diagnostic& d, const Graph& open) {
  std::string id = d.node;
  // In another file (a subgraph's): the instance in this one that it was reached through.
  if (d.where.file != open.file) {
    id.clear();
    for (const auto& note : d.locatedNotes)
      if (note.where.file == open.file && !note.node.empty()) id = note.node;
  }
  id = id.substr(0, id.find('/'));  // a node inside an instance is "instance/node"
  return !id.empty() && open.findNode(id) ? id : "";
}

}  // namespace wg::editor
