#pragma once
// What the editor shows of a node whose type reads a file (a glsl_function node, core/
// file_node.h): its ports and options from the .glsl file as it is now. The registry's maker
// reads and checks the file (glslang) as compiling does; its answer is remembered by the
// file's stamp (modification time, size, inode) and the node's options, so the canvas, which
// asks every frame, parses a file again only when it or the node changes. Any other node:
// portsOfGraphNode (core/graph_node_type.h).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/graph.h"
#include "core/node_spec.h"
#include "core/registry.h"

namespace wg::editor {

// The node's own type as its file makes it, or null (not a file node, or the file does not
// read or check: compiling reports why, at the file's line and column).
std::shared_ptr<const NodeSpec> fileNodeSpecOf(const Graph& graph, const Registry& registry, const Node& node);

// portsOfGraphNode, with a file node's ports from its file.
std::optional<NodePorts> editorPortsOf(const Graph& graph, const Registry& registry, const Node& node);

// The files the graph's file nodes name (a subgraph's too, relative to its folder), each
// once: what the editor watches besides the graph files, to recompile when one changes.
std::vector<std::string> functionFilesOf(const Graph& graph, const Registry& registry);

}  // namespace wg::editor
