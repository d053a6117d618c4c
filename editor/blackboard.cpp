#include "editor/blackboard.h"

#include <imgui.h>

#include <array>
#include <functional>

#include "editor/widget_rects.h"

namespace wg::editor {
namespace {

// For scripts: the field and button of the open name dialog (one at a time).
void noteLastItem(const char* name) {
  widgetRects().note(name, {ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y, ImGui::GetItemRectMax().x, ImGui::GetItemRectMax().y});
}

// A text field for a new name; Enter or the button tries `apply`, whose refusal stays
// under the field (in red) until the text changes. True when applied.
bool nameField(const char* id, char (&buffer)[65], std::string& refusal, const char* button,
               const std::function<std::string(const std::string&)>& apply) {
  ImGui::SetNextItemWidth(160);
  bool enter = ImGui::InputTextWithHint(id, "new name", buffer, sizeof buffer, ImGuiInputTextFlags_EnterReturnsTrue);
  noteLastItem("blackboard field");
  if (ImGui::IsItemEdited()) refusal.clear();
  ImGui::SameLine();
  bool applied = false;
  bool pressed = ImGui::Button(button);
  noteLastItem("blackboard button");
  if (pressed || enter) {
    refusal = apply(buffer);
    applied = refusal.empty();
  }
  if (!refusal.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", refusal.c_str());
  return applied;
}

// One pending rename or new name at a time (one inspector).
char blackboardName[65] = "";
std::string blackboardRefusal;
int newParameterType = 0;  // index into kBlackboardTypes
constexpr std::array<const char*, 4> kBlackboardTypes{"float", "vec2", "vec3", "vec4"};

}  // namespace

void drawBlackboardControls(GraphEditor& editor) {
  if (ImGui::Button("+ parameter")) {
    blackboardName[0] = '\0', blackboardRefusal.clear();
    ImGui::OpenPopup("new parameter");
  }
  if (ImGui::BeginPopup("new parameter")) {
    ImGui::SetNextItemWidth(80);
    ImGui::Combo("type", &newParameterType, kBlackboardTypes.data(), static_cast<int>(kBlackboardTypes.size()));
    bool added = nameField("name##new parameter", blackboardName, blackboardRefusal, "add", [&](const std::string& name) {
      Parameter p;
      p.name = name;
      p.type = *parseType(kBlackboardTypes[static_cast<size_t>(newParameterType)]);
      return editor.addParameter(std::move(p));
    });
    if (added) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  const Graph& g = editor.graph();
  ImGui::SameLine();
  if (ImGui::Button("save values as preset")) {
    blackboardName[0] = '\0', blackboardRefusal.clear();
    ImGui::OpenPopup("new preset");
  }
  if (ImGui::BeginPopup("new preset")) {
    if (nameField("name##new preset", blackboardName, blackboardRefusal, "create",
                  [&](const std::string& name) { return editor.createPreset(name); }))
      ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  if (g.presets.empty()) return;
  ImGui::SameLine();
  if (ImGui::Button("presets...")) ImGui::OpenPopup("edit presets");
  if (ImGui::BeginPopup("edit presets")) {
    std::string renameOf, deleteOf;
    for (const Preset& p : g.presets) {
      ImGui::PushID(p.name.c_str());
      ImGui::TextUnformatted(p.name.c_str());
      ImGui::SameLine(140);
      if (ImGui::SmallButton("rename")) renameOf = p.name;
      ImGui::SameLine();
      if (ImGui::SmallButton("delete")) deleteOf = p.name;
      ImGui::PopID();
    }
    static std::string renaming;
    if (!renameOf.empty()) renaming = renameOf, blackboardName[0] = '\0', blackboardRefusal.clear();
    if (!deleteOf.empty()) editor.deletePreset(deleteOf), renaming.clear();
    if (!renaming.empty() && editor.graph().findPreset(renaming)) {
      ImGui::Separator();
      ImGui::Text("rename %s to", renaming.c_str());
      if (nameField("##preset name", blackboardName, blackboardRefusal, "rename",
                    [&](const std::string& to) { return editor.renamePreset(renaming, to); }))
        renaming.clear();
    }
    ImGui::EndPopup();
  }
}

void drawParameterMenu(GraphEditor& editor, const std::string& name) {
  if (ImGui::IsItemClicked(ImGuiMouseButton_Right)) blackboardName[0] = '\0', blackboardRefusal.clear();
  if (!ImGui::BeginPopupContextItem("parameter menu")) return;
  ImGui::TextDisabled("rename %s to", name.c_str());
  if (nameField("##rename", blackboardName, blackboardRefusal, "rename",
                [&](const std::string& to) { return editor.renameParameter(name, to); }))
    ImGui::CloseCurrentPopup();
  const auto& ps = editor.graph().parameters;
  size_t at = 0;
  while (at < ps.size() && ps[at].name != name) ++at;
  if (at > 0 && ImGui::Selectable("move up", false, ImGuiSelectableFlags_DontClosePopups)) editor.moveParameter(name, at - 1);
  if (at + 1 < ps.size() && ImGui::Selectable("move down", false, ImGuiSelectableFlags_DontClosePopups)) editor.moveParameter(name, at + 1);
  if (ImGui::Selectable("delete", false, ImGuiSelectableFlags_DontClosePopups)) {
    blackboardRefusal = editor.deleteParameter(name);
    if (blackboardRefusal.empty()) ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

}  // namespace wg::editor
