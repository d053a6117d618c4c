#include "editor/inspector.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <vector>

#include "core/number_format.h"

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

}  // namespace

void drawParameterInspector(GraphEditor& editor) {
  const Graph& g = editor.graph();
  if (g.parameters.empty()) ImGui::TextDisabled("this graph has no parameters");
  for (const Parameter& p : g.parameters) {
    ImGui::PushID(p.name.c_str());
    std::vector<float> v(p.defaultValue.begin(), p.defaultValue.end());
    bool bounded = p.min && p.max;
    float lo = static_cast<float>(p.min.value_or(-1e6)), hi = static_cast<float>(p.max.value_or(1e6));
    std::string label = p.name + (p.isStatic ? " (static)" : "");
    bool changed = false;
    if (p.hint == "color" && v.size() == 3) changed = ImGui::ColorEdit3(label.c_str(), v.data(), ImGuiColorEditFlags_Float);
    else if (p.hint == "color" && v.size() == 4) changed = ImGui::ColorEdit4(label.c_str(), v.data(), ImGuiColorEditFlags_Float);
    else if (!v.empty()) changed = editFloats(label.c_str(), v, lo, hi, bounded);
    if (changed) {
      std::vector<double> d(v.begin(), v.end());
      for (double& x : d) x = std::clamp(x, p.min.value_or(-1e30), p.max.value_or(1e30));
      editor.setParameterDefault(p.name, d);
    }
    sealAfterEdit(editor);
    if (ImGui::IsItemHovered() && (!p.description.empty() || p.isStatic))
      ImGui::SetTooltip("%s%s", p.description.c_str(),
                        p.isStatic ? "\nstatic: folded into the shader, so a change recompiles" : "");
    ImGui::PopID();
  }
}

void drawNodeInspector(GraphEditor& editor, const Registry& registry, const std::string& nodeId) {
  const Node* n = editor.graph().findNode(nodeId);
  if (!n) {
    ImGui::TextDisabled("no node selected (click one on the canvas)");
    return;
  }
  const NodeSpec* spec = registry.find(n->type);
  ImGui::Text("%s : %s", n->id.c_str(), n->type.c_str());
  if (spec) ImGui::TextWrapped("%s", spec->summary.c_str());
  if (!spec) return;
  ImGui::Separator();
  std::string id = n->id;  // `n` may move when an edit reallocates the node list
  for (const PortSpec& port : spec->inputs) {
    ImGui::PushID(port.name.c_str());
    const InputSource* src = nullptr;
    for (const auto& in : editor.graph().findNode(id)->inputs)
      if (in.port == port.name) src = &in.source;
    InputTarget target{id, port.name};
    if (src && src->kind == InputSource::Kind::NodeOutput) {
      ImGui::Text("%s <- %s.%s", port.name.c_str(), src->node.c_str(), src->port.c_str());
    } else if (src && src->kind == InputSource::Kind::Parameter) {
      ImGui::Text("%s <- $%s", port.name.c_str(), src->parameter.c_str());
    } else {
      std::vector<float> v;
      if (src) v.assign(src->literal.begin(), src->literal.end());
      else if (port.defaultValue) for (int i = 0; i < port.defaultValue->size(); ++i) v.push_back(static_cast<float>((*port.defaultValue)[i]));
      if (v.empty()) {
        ImGui::Text("%s: %s", port.name.c_str(),
                    port.defaultBuiltin ? ("builtin " + std::string(builtinName(*port.defaultBuiltin))).c_str() : "(required)");
      } else if (editFloats(port.name.c_str(), v, 0, 0, false)) {
        editor.setInputConstant(target, std::vector<double>(v.begin(), v.end()));
      }
      sealAfterEdit(editor);
    }
    if (src) {
      ImGui::SameLine();
      if (ImGui::SmallButton("x")) editor.disconnect(target);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("disconnect: back to the port's default");
    }
    if (ImGui::IsItemHovered() && !port.doc.empty()) ImGui::SetTooltip("%s", port.doc.c_str());
    ImGui::PopID();
  }
  const Node* now = editor.graph().findNode(id);
  if (now && !now->options.empty()) {
    ImGui::Separator();
    for (const auto& o : now->options) ImGui::Text("option %s = %s", o.name.c_str(), o.value.dump().c_str());
  }
}

}  // namespace wg::editor
