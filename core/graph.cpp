#include "core/graph.h"

namespace wg {

const Node* Graph::findNode(std::string_view id) const {
  for (const auto& n : nodes)
    if (n.id == id) return &n;
  return nullptr;
}

const Parameter* Graph::findParameter(std::string_view name) const {
  for (const auto& p : parameters)
    if (p.name == name) return &p;
  return nullptr;
}

const Preset* Graph::findPreset(std::string_view name) const {
  for (const auto& p : presets)
    if (p.name == name) return &p;
  return nullptr;
}

const Import* Graph::findImport(std::string_view name) const {
  for (const auto& i : imports)
    if (i.name == name) return &i;
  return nullptr;
}

const Frame* Graph::findFrame(std::string_view id) const {
  for (const auto& f : frames)
    if (f.id == id) return &f;
  return nullptr;
}

nlohmann::json writtenOptions(const Node& node) {
  nlohmann::json written = nlohmann::json::object();
  for (const auto& o : node.options) written[o.name] = o.value;
  return written;
}

bool isIdentifier(std::string_view s) {
  if (s.empty() || s.size() > 64) return false;
  auto alpha = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; };
  if (!alpha(s[0])) return false;
  for (char c : s)
    if (!alpha(c) && !(c >= '0' && c <= '9')) return false;
  return true;
}

}  // namespace wg
