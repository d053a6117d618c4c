#pragma once
// The editor's scripted mode (--script edits.json): a JSON list of steps, each an object
// with "op". Graph edits go through the same GraphEditor the UI uses; the other steps
// (save, screenshots, waiting for a reload) are run by the app. docs/editor.md lists them.
//
//   [{"op": "set_parameter", "name": "shallow", "value": [0.1, 0.5, 0.4]},
//    {"op": "connect", "from": "radius.out", "to": "depth.a"},
//    {"op": "save"}, {"op": "screenshot", "path": "after.png"}]
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/graph_edit.h"
#include "core/registry.h"

namespace wg::editor {

struct ScriptStep {
  std::string op;
  nlohmann::json args;  // the whole step object
  int index = 0;        // 1-based, for messages
};

// Reads and checks the list's shape (each step an object with a known "op"). On failure
// returns empty and sets *error to one line naming the file and step.
std::optional<std::vector<ScriptStep>> loadScript(const std::string& path, std::string* error);

// True for the ops that edit the graph (applyEditStep handles them).
bool isEditOp(const std::string& op);
// What the authoring edits (delete with reconnection, an expression's inputs, a texture
// choice) need besides the graph: the node types, and the folder textures are relative to.
struct EditContext {
  const Registry* registry = nullptr;  // null: those ops are refused
  std::string graphDir;                // the edited file's folder ("" : the working folder)
};

// Applies one edit step; "" on success, else why it was refused.
std::string applyEditStep(GraphEditor& editor, const ScriptStep& step, const EditContext& context = {});

}  // namespace wg::editor
