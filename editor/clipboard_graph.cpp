#include "editor/clipboard_graph.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "core/graph_io.h"
#include "core/load_limits.h"

namespace wg::editor {

std::string copyNodesAsJson(const Graph& graph, const std::vector<std::string>& ids) {
  std::set<std::string> chosen(ids.begin(), ids.end());
  Graph clip;
  clip.name = "clipboard";
  clip.description = "nodes copied in watergraph-editor";
  for (const Node& n : graph.nodes) {
    if (!chosen.count(n.id)) continue;
    Node copy = n;
    std::erase_if(copy.inputs, [&](const NodeInput& in) {
      return in.source.kind == InputSource::Kind::NodeOutput && !chosen.count(in.source.name);
    });
    clip.nodes.push_back(std::move(copy));
  }
  return saveGraph(clip);
}

NodesToPaste nodesToPaste(const Graph& target, const std::string& text, std::array<double, 2> at) {
  NodesToPaste out;
  if (text.size() > kMaxFileBytes) {
    out.error = "the clipboard holds " + std::to_string(text.size()) + " bytes, more than a graph file may";
    return out;
  }
  // Nodes written by hand (or by another tool) need not be a whole graph file: what the
  // file format requires beyond the nodes is filled in.
  std::string asFile = text;
  nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
  if (!doc.is_discarded() && doc.is_object() && doc.contains("nodes")) {
    if (!doc.contains("version")) doc["version"] = kGraphFormatVersion;
    if (!doc.contains("name")) doc["name"] = "clipboard";
    if (!doc.contains("outputs")) doc["outputs"] = nlohmann::json::object();
    asFile = doc.dump(1);
  }
  Diagnostics d;
  auto clip = parseGraph(asFile, "clipboard", d);
  if (!clip) {
    std::string why = d.all().empty() ? "" : ": " + d.sorted().front().message;
    out.error = "the clipboard does not hold a graph (copied nodes are a graph file)" + why;
    return out;
  }
  if (clip->nodes.empty()) {
    out.error = "the clipboard's graph has no nodes";
    return out;
  }
  if (clip->nodes.size() > kMaxPastedNodes) {
    out.error = "the clipboard holds " + std::to_string(clip->nodes.size()) + " nodes; a paste takes at most " +
                std::to_string(kMaxPastedNodes);
    return out;
  }
  std::set<std::string> taken;
  for (const Node& n : target.nodes) taken.insert(n.id);
  std::map<std::string, std::string> renamed;
  for (const Node& n : clip->nodes) {
    if (renamed.count(n.id)) {
      out.error = "node id '" + n.id + "' is given twice in the clipboard";
      return out;
    }
    std::string id = n.id;
    for (int k = 2; taken.count(id); ++k) {
      std::string suffix = "_" + std::to_string(k);
      id = n.id.substr(0, std::min(n.id.size(), 64 - suffix.size())) + suffix;
    }
    taken.insert(id);
    renamed[n.id] = id;
  }
  double left = 0, top = 0;
  bool placed = false;
  for (const Node& n : clip->nodes)
    if (n.editorPosition) {
      left = placed ? std::min(left, (*n.editorPosition)[0]) : (*n.editorPosition)[0];
      top = placed ? std::min(top, (*n.editorPosition)[1]) : (*n.editorPosition)[1];
      placed = true;
    }
  for (Node n : clip->nodes) {
    n.id = renamed[n.id];
    std::erase_if(n.inputs, [&](const NodeInput& in) {
      if (in.source.kind == InputSource::Kind::NodeOutput) return !renamed.count(in.source.name);
      if (in.source.kind == InputSource::Kind::Parameter) return !target.findParameter(in.source.name);
      return false;
    });
    for (NodeInput& in : n.inputs)
      if (in.source.kind == InputSource::Kind::NodeOutput) in.source.name = renamed[in.source.name];
    std::array<double, 2> p = n.editorPosition.value_or(std::array<double, 2>{left, top});
    n.editorPosition = std::array<double, 2>{std::round(at[0] + p[0] - left), std::round(at[1] + p[1] - top)};
    n.where.file = n.idWhere.file = n.typeWhere.file = target.file;
    out.nodes.push_back(std::move(n));
  }
  return out;
}

std::string pasteNodes(GraphEditor& editor, const std::string& text, std::array<double, 2> at, std::vector<std::string>* added) {
  NodesToPaste paste = nodesToPaste(editor.graph(), text, at);
  if (!paste.error.empty()) return paste.error;
  std::vector<std::string> ids;
  for (const Node& n : paste.nodes) ids.push_back(n.id);
  if (std::string why = editor.insertNodes(std::move(paste.nodes)); !why.empty()) return why;
  if (added) *added = std::move(ids);
  return "";
}

}  // namespace wg::editor
