#pragma once
// A node type whose ports and code come from a file beside the graph: a GLSL function node
// (nodes/glsl_function_node.h) names a .glsl file and a function in it, and that function's
// parameters are its ports. The registry holds one maker per such type name; resolve asks
// it for each node of the type, and the maker reads and checks the file and hands back the
// node's own NodeSpec (its ports, its GLSL renamed into its namespace, its reference), or
// reports why not. The Program keeps the specs its ops point at.
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "core/diagnostic.h"
#include "core/graph.h"
#include "core/node_spec.h"

namespace wg {

struct Program;

struct FileNodeRequest {
  const Node& node;        // as the graph file writes it
  std::string graphDir;    // the folder of the graph file that holds the node ("" for the working folder)
  int namespaceIndex = 0;  // unique among the file nodes of one program: names the node's namespace
};

struct FileNode {
  std::shared_ptr<const NodeSpec> spec;
  std::string path;  // the file read, as the graph names it from the working folder
};

// nullopt after reporting into the Diagnostics.
using FileNodeMaker = std::function<std::optional<FileNode>(const FileNodeRequest&, Diagnostics&)>;

// Keeps `made` in `program` (its ops point at the spec) and lists its file once among the
// program's function files, relative to the program's folder.
const NodeSpec* keepFileNode(Program& program, FileNode made);

}  // namespace wg
