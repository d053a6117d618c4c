#pragma once
// Copy, cut, paste and duplicate as graph JSON: the selected nodes are written as a graph
// file (in watergraph fmt's form) to the system clipboard, so they paste into this graph,
// another one open in another editor, or a text editor. Pasting reads the clipboard as a
// graph file and hands its nodes to GraphEditor::insertNodes, which adds all of them as one
// undo step or none.
#include <array>
#include <string>
#include <vector>

#include "core/graph.h"
#include "core/graph_edit.h"

namespace wg::editor {

// A paste of more nodes than this is refused: no one means to drop a whole large graph
// onto the canvas by accident, and the file format's own limit is far larger.
inline constexpr std::size_t kMaxPastedNodes = 10000;

// The clipboard text for nodes `ids` of `graph`: a graph file holding them with their
// options, inputs and positions. A link between two of them is kept; a link from a node
// left out is dropped (the input pastes as its default).
std::string copyNodesAsJson(const Graph& graph, const std::vector<std::string>& ids);

struct NodesToPaste {
  std::vector<Node> nodes;
  std::string error;  // set (nodes empty) when the text cannot be pasted
};

// The nodes of clipboard `text` for `target`: ids `target` already has renamed (`tint` ->
// `tint_2`), the links among them following; positions moved so the group's top left is
// at `at`; an input reading a parameter `target` does not have, or a node that is not in
// the paste, dropped. Refused (error) for text that is not a graph file, holds no nodes or
// more than kMaxPastedNodes, or gives a node id twice. Unknown types and cycles are
// refused by insertNodes.
NodesToPaste nodesToPaste(const Graph& target, const std::string& text, std::array<double, 2> at);

// Pastes clipboard `text` into the editor's graph at `at`, as one undo step: "" and the new
// ids in *added, or why not, the graph and its undo history unchanged.
std::string pasteNodes(GraphEditor& editor, const std::string& text, std::array<double, 2> at, std::vector<std::string>* added);

}  // namespace wg::editor
