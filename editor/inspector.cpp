#include "editor/inspector.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "core/color_parameters.h"
#include "core/expand.h"
#include "core/graph_node_type.h"
#include "core/load_limits.h"
#include "core/node_options.h"
#include "core/number_format.h"
#include "editor/authoring_widgets.h"
#include "editor/blackboard.h"
#include "editor/function_node_ports.h"
#include "editor/slider_value.h"
#include "editor/widget_rects.h"
#include "nodes/glsl_function_node.h"

namespace wg::editor {
namespace {

// A drag or slider ends: the next change starts a new undo step.
void sealAfterEdit(GraphEditor& editor) {
  if (ImGui::IsItemDeactivatedAfterEdit()) editor.seal();
}

bool editFloats(const char* label, std::vector<float>& v, float lo, float hi, bool bounded) {
  int n = static_cast<int>(v.size());
  if (bounded) return ImGui::SliderScalarN(label, ImGuiDataType_Float, v.data(), n, &lo, &hi, "%.3f");
  return ImGui::DragScalarN(label, ImGuiDataType_Float, v.data(), n, 0.01f, nullptr, nullptr, "%.3f");
}

// The fault in red, then the line of the option's text it is on with a caret under its
// byte (ImGui's default font is monospaced).
void drawTextFault(const std::string& text, std::size_t offset, const std::string& message) {
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
  ImGui::TextWrapped("%s", message.c_str());
  offset = std::min(offset, text.size());
  size_t lineStart = offset == 0 ? std::string::npos : text.rfind('\n', offset - 1);
  lineStart = lineStart == std::string::npos ? 0 : lineStart + 1;
  size_t lineEnd = text.find('\n', offset);
  ImGui::TextUnformatted(text.substr(lineStart, lineEnd == std::string::npos ? std::string::npos : lineEnd - lineStart).c_str());
  ImGui::TextUnformatted((std::string(offset - lineStart, ' ') + "^").c_str());
  ImGui::PopStyleColor();
}

// The expansion's fault for a node's written options, computed again only when they
// change (the inspector is drawn every frame).
const std::optional<ExpansionFault>& cachedExpansionFault(const Registry& registry, const NodeSpec& spec,
                                                          const nlohmann::json& written) {
  static std::string key;
  static std::optional<ExpansionFault> fault;
  std::string now = spec.type + written.dump();
  if (now != key) {
    key = std::move(now);
    fault = expansionFault(registry, spec, written);
  }
  return fault;
}

// A text field over a string option; the option is set as the user types (one undo step
// per edit, sealed when the field is left).
void editTextOption(GraphEditor& editor, const std::string& id, const OptionSpec& o, const std::string& label,
                    const std::string& text) {
  std::vector<char> buffer(kMaxStringBytes + 1, '\0');
  std::copy_n(text.begin(), std::min(text.size(), kMaxStringBytes), buffer.begin());
  if (ImGui::InputTextMultiline(label.c_str(), buffer.data(), buffer.size(), ImVec2(-1, ImGui::GetTextLineHeight() * 3.5f)))
    editor.setOption(id, o.name, std::string(buffer.data()));
  sealAfterEdit(editor);
}

// A JSON option as text: set when the text is valid JSON and the field is left (Enter);
// otherwise the parse error shows under it and the option keeps its value.
void editJsonOption(GraphEditor& editor, const std::string& id, const OptionSpec& o, const std::string& label,
                    const nlohmann::json& value) {
  ImGui::PushID("json");
  ImGuiStorage* storage = ImGui::GetStateStorage();
  ImGuiID errorKey = ImGui::GetID("error");
  std::string text = value.dump();
  std::vector<char> buffer(kMaxStringBytes + 1, '\0');
  std::copy_n(text.begin(), std::min(text.size(), kMaxStringBytes), buffer.begin());
  if (ImGui::InputText(label.c_str(), buffer.data(), buffer.size(), ImGuiInputTextFlags_EnterReturnsTrue)) {
    nlohmann::json parsed = nlohmann::json::parse(buffer.data(), nullptr, false);
    storage->SetBool(errorKey, parsed.is_discarded());
    if (!parsed.is_discarded()) {
      std::string why = editor.setOption(id, o.name, parsed);
      if (!why.empty()) storage->SetBool(errorKey, true);
      editor.seal();
    }
  }
  if (storage->GetBool(errorKey)) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "not set: the text is not valid JSON for this option");
  ImGui::PopID();
}

// A port's type (a subgraph's are all fixed) and what it is.
std::string portTooltip(const PortSpec& port) {
  std::string type = port.kind == PortKind::Fixed ? std::string(typeName(port.type))
                     : port.kind == PortKind::Gen ? "float to vec4"
                                                  : "";
  if (port.doc.empty() || type.empty()) return type + port.doc;
  return type + ": " + port.doc;
}

}  // namespace

void drawParameterInspector(GraphEditor& editor) {
  drawBlackboardControls(editor);
  const Graph& g = editor.graph();
  if (!g.presets.empty()) {
    // A preset writes its values into the parameters (one undo step); the sliders then
    // show them, and saving keeps them as the defaults.
    if (ImGui::BeginCombo("preset", "apply a preset...")) {
      std::string chosen;
      for (const Preset& p : g.presets)
        if (ImGui::Selectable(p.name.c_str())) chosen = p.name;
      ImGui::EndCombo();
      if (!chosen.empty()) editor.applyPreset(chosen);
    }
  }
  if (g.parameters.empty()) ImGui::TextDisabled("this graph has no parameters");
  // A copy: the right-click menu may rename, move or delete parameters as the list is drawn.
  const std::vector<Parameter> parameters = g.parameters;
  for (const Parameter& p : parameters) {
    ImGui::PushID(p.name.c_str());
    std::vector<float> v(p.defaultValue.begin(), p.defaultValue.end());
    bool bounded = p.min && p.max;
    float lo = static_cast<float>(p.min.value_or(-1e6)), hi = static_cast<float>(p.max.value_or(1e6));
    std::string label = p.name + (p.isStatic ? " (static)" : "");
    bool changed = false;
    // A colour parameter's value is the sRGB colour the picker shows (the shader linearises
    // it), so the picker edits it as it is; an HDR colour may go past 1.
    const bool color = isColorHint(p.hint);
    const ImGuiColorEditFlags flags = ImGuiColorEditFlags_Float | (p.hint == kHdrColorHint ? ImGuiColorEditFlags_HDR : 0);
    if (color && v.size() == 3) changed = ImGui::ColorEdit3(label.c_str(), v.data(), flags);
    else if (color && v.size() == 4) changed = ImGui::ColorEdit4(label.c_str(), v.data(), flags);
    else if (!v.empty()) changed = editFloats(label.c_str(), v, lo, hi, bounded);
    widgetRects().note("parameter " + p.name, {ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y,
                                               ImGui::GetItemRectMax().x, ImGui::GetItemRectMax().y});
    if (changed) {
      std::vector<double> d = valuesFromWidget(p.defaultValue, v);
      for (double& x : d) x = std::clamp(x, p.min.value_or(-1e30), p.max.value_or(1e30));
      editor.setParameterDefault(p.name, d);
    }
    sealAfterEdit(editor);
    if (ImGui::IsItemHovered() && (!p.description.empty() || p.isStatic))
      ImGui::SetTooltip("%s%s", p.description.c_str(),
                        p.isStatic ? "\nstatic: folded into the shader, so a change recompiles" : "");
    drawParameterMenu(editor, p.name);  // right-click on the slider
    ImGui::PopID();
  }
}

bool drawNodeInspector(GraphEditor& editor, const Registry& registry, const std::string& nodeId, const std::string& graphDir) {
  const Node* n = editor.graph().findNode(nodeId);
  if (!n) {
    ImGui::TextDisabled("no node selected (click one on the canvas)");
    return false;
  }
  const GraphNodeType type = nodeTypeOf(editor.graph(), registry, n->type);
  // A function node's type is made from its file (its ports, and a texture option per
  // sampler2D parameter); null while the file does not check (the errors say why).
  std::shared_ptr<const NodeSpec> fileSpec = fileNodeSpecOf(editor.graph(), registry, *n);
  const NodeSpec* spec = fileSpec ? fileSpec.get() : type.spec;
  static const NodeSpec functionFallback = [] {  // its options, to mend the file's name
    NodeSpec f;
    f.type = kGlslFunctionType;
    f.summary = "a function of a .glsl file; the file does not check yet (see the errors)";
    f.options = glslFunctionOptions();
    return f;
  }();
  if (!spec && n->type == kGlslFunctionType) spec = &functionFallback;
  ImGui::Text("%s : %s", n->id.c_str(), n->type.c_str());
  if (spec) ImGui::TextWrapped("%s", spec->summary.c_str());
  bool open = false;
  if (type.isInstance()) {
    const Graph* sub = type.import->graph.get();
    if (sub && sub->interface && !sub->interface->description.empty()) ImGui::TextWrapped("%s", sub->interface->description.c_str());
    ImGui::TextDisabled("subgraph %s%s", type.import->path.c_str(), sub ? "" : " (did not load: see the errors)");
    ImGui::BeginDisabled(!sub);
    open = ImGui::Button("Open subgraph");
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("edit %s here; \"back\" returns to this graph", type.import->path.c_str());
  }
  std::optional<NodePorts> known = editorPortsOf(editor.graph(), registry, *n);
  if (!known) return open;
  ImGui::Separator();
  std::string id = n->id;  // `n` may move when an edit reallocates the node list
  const NodePorts ports = std::move(*known);
  for (const PortSpec& port : ports.inputs) {
    ImGui::PushID(port.name.c_str());
    const InputSource* src = nullptr;
    for (const auto& in : editor.graph().findNode(id)->inputs)
      if (in.port == port.name) src = &in.source;
    InputTarget target{id, port.name};
    if (src && src->kind == InputSource::Kind::NodeOutput) {
      ImGui::Text("%s <- %s.%s", port.name.c_str(), src->name.c_str(), src->port.c_str());
    } else if (src && src->kind == InputSource::Kind::Parameter) {
      ImGui::Text("%s <- $%s", port.name.c_str(), src->name.c_str());
    } else {
      std::vector<double> exact;
      if (src) exact = src->literal;
      else if (port.defaultValue) for (int i = 0; i < port.defaultValue->size(); ++i) exact.push_back((*port.defaultValue)[i]);
      std::vector<float> v(exact.begin(), exact.end());
      if (v.empty()) {
        ImGui::Text("%s: %s", port.name.c_str(),
                    port.defaultBuiltin ? ("builtin " + std::string(builtinName(*port.defaultBuiltin))).c_str() : "(required)");
      } else if (editFloats(port.name.c_str(), v, 0, 0, false)) {
        editor.setInputConstant(target, valuesFromWidget(exact, v));
      }
      sealAfterEdit(editor);
    }
    if (std::string tip = portTooltip(port); ImGui::IsItemHovered() && !tip.empty()) ImGui::SetTooltip("%s", tip.c_str());
    if (src) {
      ImGui::SameLine();
      if (ImGui::SmallButton("x")) editor.disconnect(target);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("disconnect: back to the port's default");
    }
    ImGui::PopID();
  }
  if (!spec) return open;  // an instance has no options
  if (!spec->options.empty()) ImGui::Separator();
  for (const OptionSpec& o : spec->options) {
    const Node* now = editor.graph().findNode(id);
    if (!now) break;
    nlohmann::json value = o.defaultValue;
    for (const auto& set : now->options)
      if (set.name == o.name) value = set.value;
    ImGui::PushID(o.name.c_str());
    std::string label = "option " + o.name;
    switch (o.kind) {
      case OptionSpec::Kind::Enum: {
        std::string current = value.is_string() ? value.get<std::string>() : "";
        if (ImGui::BeginCombo(label.c_str(), current.c_str())) {
          for (const auto& choice : o.choices)
            if (ImGui::Selectable(choice.c_str(), choice == current)) editor.setOption(id, o.name, choice);
          ImGui::EndCombo();
        }
        break;
      }
      case OptionSpec::Kind::Bool: {
        bool b = value.is_boolean() && value.get<bool>();
        if (ImGui::Checkbox(label.c_str(), &b)) editor.setOption(id, o.name, b);
        break;
      }
      case OptionSpec::Kind::Number:
      case OptionSpec::Kind::Integer: {
        bool integer = o.kind == OptionSpec::Kind::Integer;
        double x = value.is_number() ? value.get<double>() : 0;
        double lo = o.min.value_or(-1e9), hi = o.max.value_or(1e9);
        bool changed = integer ? ImGui::DragScalar(label.c_str(), ImGuiDataType_Double, &x, 0.1f, &lo, &hi, "%.0f")
                               : ImGui::DragScalar(label.c_str(), ImGuiDataType_Double, &x, 0.01f, &lo, &hi, "%.3f");
        if (changed) {
          x = std::clamp(integer ? std::round(x) : x, lo, hi);
          integer ? editor.setOption(id, o.name, static_cast<long long>(x)) : editor.setOption(id, o.name, x);
        }
        sealAfterEdit(editor);
        break;
      }
      case OptionSpec::Kind::Text: {
        editTextOption(editor, id, o, label, value.is_string() ? value.get<std::string>() : "");
        // A node that expands its options (an expression's formula): the fault inline.
        const Node* edited = editor.graph().findNode(id);
        if (spec->expand && edited) {
          nlohmann::json written = writtenOptions(*edited);
          const auto& fault = cachedExpansionFault(registry, *spec, written);
          if (fault && fault->option == o.name && value.is_string())
            drawTextFault(value.get<std::string>(), fault->offset, fault->message);
        }
        break;
      }
      case OptionSpec::Kind::Json:
        // An expression's declared inputs as a list (renames carry the formula along), the
        // JSON text under it for the rest.
        if (spec->type == "expression" && o.name == "inputs") drawExpressionInputs(editor, registry, id);
        editJsonOption(editor, id, o, label, value);
        break;
      case OptionSpec::Kind::Texture:
        drawTexturePicker(editor, registry, graphDir, id, o.name, value);
        break;
    }
    if (ImGui::IsItemHovered() && !o.doc.empty()) ImGui::SetTooltip("%s", o.doc.c_str());
    ImGui::PopID();
  }
  return open;
}

}  // namespace wg::editor
