// GraphEditor's frame edits: the titled, commented boxes the canvas draws around groups of
// nodes (Frame in core/graph.h). Layout only, as node positions are: compiling never reads
// them, but they are part of the graph's state, so undo and redo bring them back with it.
// See core/graph_edit.h.
#include <algorithm>

#include "core/graph_edit.h"
#include "core/load_limits.h"
#include "core/number_format.h"

namespace wg {

void GraphEditor::dropFromFrames(const std::set<std::string>& gone) {
  for (Frame& f : graph_.frames) std::erase_if(f.nodes, [&](const std::string& id) { return gone.count(id) > 0; });
  std::erase_if(graph_.frames, [](const Frame& f) { return f.nodes.empty(); });
}

// The checks the loader makes on a frame's "nodes" (WG013), as a refusal.
std::string GraphEditor::checkFrameNodes(const std::vector<std::string>& nodes) const {
  if (nodes.empty()) return "a frame holds at least one node (select some first)";
  std::set<std::string> seen;
  for (const std::string& id : nodes) {
    if (!graph_.findNode(id)) return "no node '" + id + "'";
    if (!seen.insert(id).second) return "node '" + id + "' is listed twice";
  }
  return "";
}

// `frame` (in graph_ or about to be) holds exactly `nodes`; other frames let them go.
void GraphEditor::takeIntoFrame(Frame& frame, std::vector<std::string> nodes) {
  std::set<std::string> taken(nodes.begin(), nodes.end());
  for (Frame& other : graph_.frames)
    if (&other != &frame) std::erase_if(other.nodes, [&](const std::string& id) { return taken.count(id) > 0; });
  frame.nodes = std::move(nodes);
  std::erase_if(graph_.frames, [&](const Frame& f) { return &f != &frame && f.nodes.empty(); });
}

std::string GraphEditor::addFrame(Frame frame, std::string* usedId) {
  if (std::string why = checkFrameNodes(frame.nodes); !why.empty()) return why;
  if (frame.id.empty())
    for (int n = 1; frame.id.empty() || graph_.findFrame(frame.id); ++n) frame.id = "frame_" + std::to_string(n);
  if (!isIdentifier(frame.id)) return "'" + frame.id + "' is not a frame id ([A-Za-z_][A-Za-z0-9_]*, at most 64)";
  if (graph_.findFrame(frame.id)) return "a frame '" + frame.id + "' already exists";
  if (frame.title.size() > kMaxStringBytes || frame.comment.size() > kMaxStringBytes)
    return "a frame's title and comment are at most " + std::to_string(kMaxStringBytes) + " bytes each";
  record("add frame '" + frame.id + "'", "");
  std::vector<std::string> nodes = std::move(frame.nodes);
  frame.where = SourceRef{graph_.file, 0, 0};
  frame.nodesWhere = frame.where;
  graph_.frames.push_back(std::move(frame));
  // The new frame is the last one: erasing emptied frames before it leaves it last.
  takeIntoFrame(graph_.frames.back(), std::move(nodes));
  if (usedId) *usedId = graph_.frames.back().id;
  return "";
}

std::string GraphEditor::setFrameText(const std::string& id, const std::string& title, const std::string& comment) {
  const Frame* f = graph_.findFrame(id);
  if (!f) return "no frame '" + id + "'";
  if (title.size() > kMaxStringBytes || comment.size() > kMaxStringBytes)
    return "a frame's title and comment are at most " + std::to_string(kMaxStringBytes) + " bytes each";
  if (f->title == title && f->comment == comment) return "";
  record("edit frame '" + id + "'", "");
  for (Frame& frame : graph_.frames)
    if (frame.id == id) frame.title = title, frame.comment = comment;
  return "";
}

std::string GraphEditor::setFrameNodes(const std::string& id, const std::vector<std::string>& nodes) {
  if (!graph_.findFrame(id)) return "no frame '" + id + "'";
  if (std::string why = checkFrameNodes(nodes); !why.empty()) return why;
  if (graph_.findFrame(id)->nodes == nodes) return "";
  record("set the nodes of frame '" + id + "'", "");
  auto frame = std::find_if(graph_.frames.begin(), graph_.frames.end(), [&](const Frame& f) { return f.id == id; });
  takeIntoFrame(*frame, nodes);  // may erase emptied frames: `frame` is not used after
  return "";
}

std::string GraphEditor::deleteFrame(const std::string& id) {
  if (!graph_.findFrame(id)) return "no frame '" + id + "'";
  record("delete frame '" + id + "'", "");
  std::erase_if(graph_.frames, [&](const Frame& f) { return f.id == id; });
  return "";
}

std::string GraphEditor::moveFrame(const std::string& id, std::array<double, 2> by) {
  const Frame* f = graph_.findFrame(id);
  if (!f) return "no frame '" + id + "'";
  std::vector<std::pair<std::string, std::array<double, 2>>> to;
  for (const std::string& n : f->nodes) {
    const Node* node = graph_.findNode(n);
    std::array<double, 2> p = node && node->editorPosition ? *node->editorPosition : std::array<double, 2>{0, 0};
    if (node) to.push_back({n, {p[0] + by[0], p[1] + by[1]}});
  }
  return moveNodes(to);
}

}  // namespace wg
