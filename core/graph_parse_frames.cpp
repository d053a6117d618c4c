// Parsing a graph file: the editor's layout ("editor": {"frames": ...}), which compiling
// never reads.
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "core/graph_parser.h"
#include "core/load_limits.h"
#include "core/suggest.h"

namespace wg::parsing {

// "editor": {"frames": {"shore": {"title": "...", "comment": "...", "nodes": ["a", "b"]}}}:
// the canvas's layout, which compiling never reads. Each frame lists at least one of the
// graph's nodes, each once, and a node lies in at most one frame (WG013).
void GraphParser::loadEditorLayout(const DraftValue& ev, Graph& g) {
  checkKeys(ev, "'editor'", {"frames"});
  auto* fv = field(ev, "frames", json::value_t::object, "the editor's 'frames'");
  if (!fv) return;
  // Sets, not scans: a hostile frame may list 10^5 ids.
  std::unordered_set<std::string_view> nodeIds;
  for (const auto& n : g.nodes) nodeIds.insert(n.id);
  std::unordered_map<std::string, std::string> frameOfNode;  // node id -> the frame listing it
  std::optional<NameSuggester> nodeNames;                     // made on the first unknown id
  const bool nodesKnown = nodeCount() <= kMaxNodes;           // else reported in the nodes' turn
  for (const DraftValue& f : fv->members) {
    Frame frame;
    frame.id = f.name;
    frame.where = ref(f.key);
    const std::string what = "frame '" + f.name + "'";
    if (!isIdentifier(frame.id))
      diags_.error(DiagCode::InvalidIdentifier, frame.where, "frame id '" + frame.id + "' is not an identifier " + kIdentifierRule);
    if (f.type != json::value_t::object) {
      diags_.error(DiagCode::WrongJsonType, ref(f.at), what + " must be an object with \"nodes\", found " + jsonTypeName(f.type));
      continue;
    }
    checkKeys(f, what, {"title", "comment", "nodes"});
    if (auto* v = field(f, "title", json::value_t::string, "'title' of " + what)) frame.title = v->value.get<std::string>();
    if (auto* v = field(f, "comment", json::value_t::string, "'comment' of " + what)) frame.comment = v->value.get<std::string>();
    const DraftValue* nv = f.member("nodes");
    if (!nv) {
      missing(f, what + " is missing \"nodes\" (the ids of the nodes it holds)");
      continue;
    }
    frame.nodesWhere = ref(nv->at);
    bool ids = nv->value.is_array();
    for (const auto& e : nv->value) ids = ids && e.is_string();
    if (!ids) {
      diags_.error(DiagCode::WrongJsonType, frame.nodesWhere, "'nodes' of " + what + " must be an array of node ids, found " + describeValue(nv->value));
      continue;
    }
    if (nv->value.empty()) diags_.error(DiagCode::InvalidFrame, frame.nodesWhere, what + " holds no nodes; a frame lists at least one");
    std::unordered_set<std::string_view> listed;
    for (const auto& e : nv->value) {
      const std::string& id = e.get_ref<const std::string&>();
      if (!listed.insert(id).second) {
        diags_.error(DiagCode::InvalidFrame, frame.nodesWhere, what + " lists node '" + id + "' twice");
        continue;
      }
      frame.nodes.push_back(id);
      if (!nodesKnown) continue;
      if (!nodeIds.count(id)) {
        if (!nodeNames) {
          std::vector<std::string> all;
          for (const auto& n : g.nodes) all.push_back(n.id);
          nodeNames.emplace(std::move(all));
        }
        diags_.error(DiagCode::InvalidFrame, frame.nodesWhere,
                     what + " lists node '" + id + "', which the graph does not have" + nodeNames->didYouMean(id));
      } else if (auto [it, fresh] = frameOfNode.emplace(id, frame.id); !fresh) {
        diags_.error(DiagCode::InvalidFrame, frame.nodesWhere,
                     what + " lists node '" + id + "', which frame '" + it->second + "' holds; a node lies in at most one frame");
      }
    }
    g.frames.push_back(std::move(frame));
  }
}

}  // namespace wg::parsing
