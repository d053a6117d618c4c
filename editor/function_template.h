#pragma once
// "New function node": writes a small .glsl file beside the graph from a template (a
// function named as the file, two inputs, a vec3 output) and adds a glsl_function node that
// calls it, so a person starts from code that compiles and edits it in their own editor (the
// node's ports follow the file as it is saved, editor/function_node_ports.h).
#include <array>
#include <string>

#include "core/graph_edit.h"
#include "core/registry.h"

namespace wg::editor {

// The template's text for a function called `name`.
std::string functionTemplateText(const std::string& name);

// Writes `graphDir`/`name`.glsl and adds the node at `position` (one undo step; the file
// stays, as a saved file does). Refused, nothing written, when `name` is not an identifier,
// is reserved (wg_, WG_, wgfn) or the file exists already (a file is never overwritten).
std::string addFunctionNodeFromTemplate(GraphEditor& editor, const Registry& registry, const std::string& graphDir,
                                        const std::string& name, std::array<double, 2> position, std::string* usedId = nullptr);

}  // namespace wg::editor
