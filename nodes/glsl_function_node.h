#pragma once
// The `glsl_function` node: a function of a .glsl file beside the graph, whose parameters
// and return value are the node's ports (docs/graph-format.md, "GLSL function nodes").
// Its type is not one spec of the registry but a maker (core/file_node.h): each node's
// spec is made from its file when the graph is resolved.
#include "core/registry.h"

namespace wg {

inline constexpr const char* kGlslFunctionType = "glsl_function";

// Makes the spec of one glsl_function node, or reports why its file cannot serve.
std::optional<FileNode> makeGlslFunctionNode(const FileNodeRequest& request, Diagnostics& diags);

// The options every glsl_function node has (file, function, reference), for the docs.
std::vector<OptionSpec> glslFunctionOptions();

}  // namespace wg
