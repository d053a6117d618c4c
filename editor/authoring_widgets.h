#pragma once
// Inspector widgets for the authoring edits: an expression node's declared inputs as a list
// (editor/expression_inputs.h) and a texture option as a picker over the graph folder's PNG
// files with thumbnails (editor/texture_choices.h). Drawn into the current ImGui window.
#include <array>
#include <string>

#include <nlohmann/json.hpp>

#include "core/graph_edit.h"
#include "core/registry.h"

namespace wg::editor {

void drawExpressionInputs(GraphEditor& editor, const Registry& registry, const std::string& nodeId);
// `graphDir`: the edited file's folder, which texture paths are relative to.
void drawTexturePicker(GraphEditor& editor, const Registry& registry, const std::string& graphDir, const std::string& nodeId,
                       const std::string& option, const nlohmann::json& value);

// In the add-node palette: a name field and "new function node", which writes NAME.glsl
// beside the graph from a template and adds a node calling it (editor/function_template.h)
// at `position`. True when a node was added; its id goes to *addedId.
bool drawNewFunctionNode(GraphEditor& editor, const Registry& registry, std::array<double, 2> position, std::string* addedId);
// Its name field had the keyboard in the last frame: Enter there is the field's, not the
// palette's.
bool newFunctionNameActive();

}  // namespace wg::editor
