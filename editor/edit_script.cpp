#include "editor/edit_script.h"

#include "core/file_read.h"
#include "core/load_limits.h"
#include "editor/dissolve_nodes.h"
#include "editor/expression_inputs.h"
#include "editor/function_template.h"
#include "editor/link_insert.h"
#include "editor/texture_choices.h"

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

namespace wg::editor {
namespace {

const std::set<std::string>& editOps() {
  static const std::set<std::string> ops{"set_parameter", "apply_preset", "set_input", "set_option", "connect", "disconnect", "add_node",
                                         "delete_node", "move_node", "undo", "redo",
                                         "add_parameter", "rename_parameter", "delete_parameter", "move_parameter",
                                         "create_preset", "rename_preset", "delete_preset", "delete_reconnect",
                                         "declare_input", "rename_input", "retype_input", "remove_input", "choose_texture", "insert_on_link", "new_function_node",
                                         "add_frame", "set_frame", "delete_frame", "move_frame"};
  return ops;
}

const std::set<std::string>& appOps() {
  static const std::set<std::string> ops{"save", "screenshot", "save_preview", "save_thumbnail", "select", "camera", "time",
                                         "frames", "external_write", "wait_reload", "open_subgraph", "back",
                                         "key", "type", "click", "drag", "wheel", "hover", "print_widgets",
                                         "set_clipboard", "save_clipboard", "save_as", "open"};
  return ops;
}

// Throws std::invalid_argument with a message naming the field.
std::string text(const nlohmann::json& step, const char* key) {
  auto it = step.find(key);
  if (it == step.end() || !it->is_string()) throw std::invalid_argument(std::string("needs a string \"") + key + "\"");
  return it->get<std::string>();
}

std::vector<double> numbers(const nlohmann::json& step, const char* key) {
  auto it = step.find(key);
  std::vector<double> out;
  if (it != step.end() && it->is_number()) return {it->get<double>()};
  if (it == step.end() || !it->is_array()) throw std::invalid_argument(std::string("needs a number or number list \"") + key + "\"");
  for (const auto& x : *it) {
    if (!x.is_number()) throw std::invalid_argument(std::string("\"") + key + "\" must hold numbers only");
    out.push_back(x.get<double>());
  }
  return out;
}

double number(const nlohmann::json& step, const char* key) {
  auto it = step.find(key);
  if (it == step.end() || !it->is_number()) throw std::invalid_argument(std::string("needs a number \"") + key + "\"");
  return it->get<double>();
}

// "node.port" -> {node, port}; an output slot ("fragment.color") when given as "to_output".
std::pair<std::string, std::string> nodePort(const std::string& s) {
  auto dot = s.find('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == s.size())
    throw std::invalid_argument("'" + s + "' is not \"node.port\"");
  return {s.substr(0, dot), s.substr(dot + 1)};
}

InputTarget target(const nlohmann::json& step) {
  if (step.contains("to_output")) return {"", text(step, "to_output")};
  if (step.contains("output")) return {"", text(step, "output")};
  if (step.contains("to")) {
    auto [n, p] = nodePort(text(step, "to"));
    return {n, p};
  }
  return {text(step, "node"), text(step, "port")};
}

Type inputType(const nlohmann::json& step) {
  auto type = parseType(text(step, "type"));
  if (!type || !isFloatScalarOrVector(*type)) throw std::invalid_argument("\"type\" is float, vec2, vec3 or vec4");
  return *type;
}

// A list of node ids under `key`.
std::vector<std::string> nodeIds(const nlohmann::json& step, const char* key) {
  auto it = step.find(key);
  if (it == step.end() || !it->is_array()) throw std::invalid_argument(std::string("needs a list of node ids \"") + key + "\"");
  std::vector<std::string> ids;
  for (const auto& id : *it) {
    if (!id.is_string()) throw std::invalid_argument(std::string("\"") + key + "\" must hold strings only");
    ids.push_back(id.get<std::string>());
  }
  return ids;
}

// The canvas's frames (core/graph_edit_frames.cpp); kNotAFrameOp for any other op.
constexpr const char* kNotAFrameOp = "\x02";
std::string applyFrameStep(GraphEditor& e, const ScriptStep& step) {
  const std::string& op = step.op;
  const auto& a = step.args;
  if (op == "add_frame") {
    Frame f;
    f.id = a.contains("id") ? text(a, "id") : "";
    f.title = a.contains("title") ? text(a, "title") : "";
    f.comment = a.contains("comment") ? text(a, "comment") : "";
    f.nodes = nodeIds(a, "nodes");
    return e.addFrame(std::move(f));
  }
  if (op == "set_frame") {
    const std::string id = text(a, "id");
    const Frame* f = e.graph().findFrame(id);
    if (!f) return "no frame '" + id + "'";
    if (a.contains("nodes"))
      if (std::string why = e.setFrameNodes(id, nodeIds(a, "nodes")); !why.empty()) return why;
    f = e.graph().findFrame(id);
    return e.setFrameText(id, a.contains("title") ? text(a, "title") : f->title, a.contains("comment") ? text(a, "comment") : f->comment);
  }
  if (op == "delete_frame") return e.deleteFrame(text(a, "id"));
  if (op == "move_frame") {
    std::vector<double> by = numbers(a, "by");
    if (by.size() != 2) throw std::invalid_argument("\"by\" is [dx, dy]");
    std::string why = e.moveFrame(text(a, "id"), {by[0], by[1]});
    e.seal();
    return why;
  }
  return kNotAFrameOp;
}

// The ops over the node types (editor/dissolve_nodes.h, expression_inputs.h,
// texture_choices.h); kNotAuthoring for any other op.
constexpr const char* kNotAuthoring = "\x01";
std::string applyAuthoringStep(GraphEditor& e, const ScriptStep& step, const EditContext& context) {
  static const std::set<std::string> ops{"delete_reconnect", "declare_input", "rename_input", "retype_input", "remove_input",
                                         "choose_texture", "insert_on_link", "new_function_node"};
  const std::string& op = step.op;
  if (!ops.count(op)) return kNotAuthoring;
  if (!context.registry) return "'" + op + "' needs the node registry";
  const Registry& r = *context.registry;
  const auto& a = step.args;
  if (op == "delete_reconnect") {
    auto it = a.find("ids");
    if (it == a.end() || !it->is_array()) throw std::invalid_argument("needs a list of node ids \"ids\"");
    std::vector<std::string> ids;
    for (const auto& id : *it) {
      if (!id.is_string()) throw std::invalid_argument("\"ids\" must hold strings only");
      ids.push_back(id.get<std::string>());
    }
    return dissolveNodes(e, r, ids);
  }
  if (op == "new_function_node") {
    double x = a.contains("x") ? number(a, "x") : 0, y = a.contains("y") ? number(a, "y") : 0;
    return addFunctionNodeFromTemplate(e, r, context.graphDir, text(a, "name"), {x, y});
  }
  if (op == "insert_on_link") {
    double x = a.contains("x") ? number(a, "x") : 0, y = a.contains("y") ? number(a, "y") : 0;
    return insertNodeOnLink(e, r, text(a, "type"), target(a), {x, y});
  }
  if (op == "declare_input") return declareExpressionInput(e, r, text(a, "node"), text(a, "name"), inputType(a));
  if (op == "retype_input") return retypeExpressionInput(e, r, text(a, "node"), text(a, "name"), inputType(a));
  if (op == "rename_input") return renameExpressionInput(e, r, text(a, "node"), text(a, "name"), text(a, "to"));
  if (op == "remove_input") return removeExpressionInput(e, r, text(a, "node"), text(a, "name"));
  return chooseTexture(e, r, context.graphDir, text(a, "node"), text(a, "option"), text(a, "path"));
}

}  // namespace

std::optional<std::vector<ScriptStep>> loadScript(const std::string& path, std::string* error) {
  FileReadRule rule;
  rule.maxBytes = kMaxFileBytes;
  FileReadFailure failure;
  auto file = readFileChecked(path, rule, &failure);  // one open, one read (core/file_read.h)
  if (!file) {
    *error = path + ": cannot read the script: " + failure.why();
    return std::nullopt;
  }
  nlohmann::json doc = nlohmann::json::parse(file->bytes, nullptr, false);
  if (doc.is_discarded() || !doc.is_array()) {
    *error = path + ": a script is a JSON list of steps, each {\"op\": ...}";
    return std::nullopt;
  }
  std::vector<ScriptStep> steps;
  int index = 0;
  for (const auto& s : doc) {
    ++index;
    std::string where = path + ": step " + std::to_string(index);
    if (!s.is_object() || !s.contains("op") || !s["op"].is_string()) {
      *error = where + ": not an object with a string \"op\"";
      return std::nullopt;
    }
    std::string op = s["op"].get<std::string>();
    if (!editOps().count(op) && !appOps().count(op)) {
      *error = where + ": unknown op '" + op + "'";
      return std::nullopt;
    }
    steps.push_back({op, s, index});
  }
  return steps;
}

bool isEditOp(const std::string& op) { return editOps().count(op) > 0; }

std::string applyEditStep(GraphEditor& e, const ScriptStep& step, const EditContext& context) {
  const auto& a = step.args;
  try {
    const std::string& op = step.op;
    if (std::string why = applyAuthoringStep(e, step, context); why != kNotAuthoring) return why;
    if (std::string why = applyFrameStep(e, step); why != kNotAFrameOp) return why;
    if (op == "set_parameter") return e.setParameterDefault(text(a, "name"), numbers(a, "value"));
    if (op == "set_input") {
      if (a.contains("parameter")) return e.setInputParameter(target(a), text(a, "parameter"));
      return e.setInputConstant(target(a), numbers(a, "value"));
    }
    if (op == "apply_preset") return e.applyPreset(text(a, "name"));
    if (op == "set_option") {
      if (!a.contains("value")) throw std::invalid_argument("needs a \"value\"");
      return e.setOption(text(a, "node"), text(a, "name"), a["value"]);
    }
    if (op == "connect") {
      auto [node, port] = nodePort(text(a, "from"));
      return e.connect(node, port, target(a));
    }
    if (op == "disconnect") return e.disconnect(target(a));
    if (op == "add_node") {
      std::string id = a.contains("id") ? text(a, "id") : "";
      double x = a.contains("x") ? number(a, "x") : 0, y = a.contains("y") ? number(a, "y") : 0;
      return e.addNode(text(a, "type"), id, {x, y});
    }
    if (op == "delete_node") return e.deleteNode(text(a, "id"));
    if (op == "move_node") return e.moveNode(text(a, "id"), {number(a, "x"), number(a, "y")});
    if (op == "add_parameter") {
      Parameter p;
      p.name = text(a, "name");
      auto type = parseType(a.contains("type") ? text(a, "type") : "float");
      if (!type) throw std::invalid_argument("\"type\" is float, vec2, vec3 or vec4");
      p.type = *type;
      if (a.contains("default")) p.defaultValue = numbers(a, "default");
      if (a.contains("min")) p.min = number(a, "min");
      if (a.contains("max")) p.max = number(a, "max");
      if (a.contains("hint")) p.hint = text(a, "hint");
      if (a.contains("description")) p.description = text(a, "description");
      if (a.contains("static")) {
        if (!a["static"].is_boolean()) throw std::invalid_argument("\"static\" must be true or false");
        p.isStatic = a["static"].get<bool>();
      }
      return e.addParameter(std::move(p));
    }
    if (op == "rename_parameter") return e.renameParameter(text(a, "name"), text(a, "to"));
    if (op == "delete_parameter") return e.deleteParameter(text(a, "name"));
    if (op == "move_parameter") {
      double index = number(a, "index");
      if (index < 0 || index != std::floor(index)) throw std::invalid_argument("\"index\" is a position from 0");
      return e.moveParameter(text(a, "name"), static_cast<size_t>(index));
    }
    if (op == "create_preset") return e.createPreset(text(a, "name"));
    if (op == "rename_preset") return e.renamePreset(text(a, "name"), text(a, "to"));
    if (op == "delete_preset") return e.deletePreset(text(a, "name"));
    if (op == "undo") return e.undo() ? "" : "nothing to undo";
    if (op == "redo") return e.redo() ? "" : "nothing to redo";
    return "'" + op + "' is not an edit";
  } catch (const std::invalid_argument& ex) {
    return ex.what();
  } catch (const nlohmann::json::exception& ex) {
    return ex.what();
  }
}

}  // namespace wg::editor
