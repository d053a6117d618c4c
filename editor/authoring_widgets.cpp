#include "editor/authoring_widgets.h"

#include <epoxy/gl.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <filesystem>
#include <map>

#include "core/png_decode.h"
#include "core/texture_check.h"
#include "editor/expression_inputs.h"
#include "editor/function_template.h"
#include "editor/texture_choices.h"
#include "editor/widget_rects.h"

namespace wg::editor {
namespace {

constexpr std::array<const char*, 4> kInputTypes{"float", "vec2", "vec3", "vec4"};
const ImVec4 kRefusalColor(1.0f, 0.45f, 0.4f, 1.0f);

void noteItem(const std::string& name) {
  widgetRects().note(name, {ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y, ImGui::GetItemRectMax().x, ImGui::GetItemRectMax().y});
}

// One refusal shown at a time (one inspector), with the node it is about.
struct AuthoringRefusal {
  std::string node, text;
};
AuthoringRefusal authoringRefusal;

void noteRefusal(const std::string& node, std::string why) { authoringRefusal = {node, std::move(why)}; }

// A small GL texture per PNG file shown in the picker, made once per file version (path,
// size and modification time) and kept for the process: a folder of textures is small.
class TextureThumbnails {
 public:
  static constexpr int kSide = 32;
  GLuint get(const std::string& realPath) {
    std::error_code ec;
    auto stamp = std::filesystem::last_write_time(realPath, ec).time_since_epoch().count();
    std::string key = realPath + "\n" + std::to_string(stamp) + "\n" + std::to_string(std::filesystem::file_size(realPath, ec));
    auto it = made_.find(key);
    if (it != made_.end()) return it->second;
    DecodedPng png;
    std::string why;
    GLuint tex = 0;
    if (made_.size() < 512 && decodePng(realPath, &png, &why) && png.width > 0 && png.height > 0) {
      // Nearest texels at kSide x kSide: a preview, not a filter.
      std::vector<unsigned char> small(kSide * kSide * 4);
      for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
          size_t sx = static_cast<size_t>(x * png.width / kSide), sy = static_cast<size_t>(y * png.height / kSide);
          std::memcpy(&small[static_cast<size_t>(y * kSide + x) * 4], &png.rgba[(sy * static_cast<size_t>(png.width) + sx) * 4], 4);
        }
      glGenTextures(1, &tex);
      glBindTexture(GL_TEXTURE_2D, tex);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kSide, kSide, 0, GL_RGBA, GL_UNSIGNED_BYTE, small.data());
      glBindTexture(GL_TEXTURE_2D, 0);
    }
    return made_[key] = tex;
  }

 private:
  std::map<std::string, GLuint> made_;
};

TextureThumbnails& textureThumbnails() {
  static TextureThumbnails t;
  return t;
}

// The listing of a folder, made again when the picker opens (files come and go).
TextureChoices& listedTextures() {
  static TextureChoices c;
  return c;
}

}  // namespace

void drawExpressionInputs(GraphEditor& editor, const Registry& registry, const std::string& nodeId) {
  const Node* n = editor.graph().findNode(nodeId);
  if (!n) return;
  nlohmann::json declared = nlohmann::json::object({{"x", "float"}});  // the option's default
  for (const NodeOption& o : n->options)
    if (o.name == "inputs") declared = o.value;
  if (!declared.is_object()) return;  // the JSON field shows what is wrong
  ImGui::TextDisabled("inputs (rename: the formula follows)");
  static std::map<std::string, std::array<char, 65>> names;  // per "node/input": the name field's text
  for (auto it = declared.begin(); it != declared.end(); ++it) {
    const std::string name = it.key();
    ImGui::PushID(name.c_str());
    auto [at, fresh] = names.try_emplace(nodeId + "/" + name);
    auto& buffer = at->second;
    if (fresh) std::snprintf(buffer.data(), buffer.size(), "%s", name.c_str());
    ImGui::SetNextItemWidth(110);
    // Renamed on Enter, or when the field is left after an edit (as a file is renamed).
    bool enter = ImGui::InputText("##name", buffer.data(), buffer.size(), ImGuiInputTextFlags_EnterReturnsTrue);
    if ((enter || ImGui::IsItemDeactivatedAfterEdit()) && name != buffer.data()) {
      std::string to = buffer.data();
      std::string why = renameExpressionInput(editor, registry, nodeId, name, to);
      noteRefusal(nodeId, why);
      if (why.empty()) names.erase(nodeId + "/" + name);
      else std::snprintf(buffer.data(), buffer.size(), "%s", name.c_str());
    }
    noteItem("expression input " + name);
    ImGui::SameLine();
    std::string type = it.value().is_string() ? it.value().get<std::string>() : "?";
    ImGui::SetNextItemWidth(70);
    if (ImGui::BeginCombo("##type", type.c_str())) {
      for (const char* t : kInputTypes)
        if (ImGui::Selectable(t, type == t)) noteRefusal(nodeId, retypeExpressionInput(editor, registry, nodeId, name, *parseType(t)));
      ImGui::EndCombo();
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("x")) noteRefusal(nodeId, removeExpressionInput(editor, registry, nodeId, name));
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("remove the input (the formula stays as written)");
    ImGui::PopID();
  }
  static std::array<char, 65> added{};
  ImGui::SetNextItemWidth(110);
  bool enter = ImGui::InputTextWithHint("##new input", "new input", added.data(), added.size(), ImGuiInputTextFlags_EnterReturnsTrue);
  noteItem("expression new input");
  ImGui::SameLine();
  bool add = ImGui::SmallButton("+ input");
  noteItem("expression add input");
  if (add || enter) {
    std::string why = declareExpressionInput(editor, registry, nodeId, added.data(), Type::Float);
    noteRefusal(nodeId, why);
    if (why.empty()) added[0] = '\0';
  }
  if (authoringRefusal.node == nodeId && !authoringRefusal.text.empty())
    ImGui::TextColored(kRefusalColor, "%s", authoringRefusal.text.c_str());
}

void drawTexturePicker(GraphEditor& editor, const Registry& registry, const std::string& graphDir, const std::string& nodeId,
                       const std::string& option, const nlohmann::json& value) {
  std::string current = value.is_string() ? value.get<std::string>() : "";
  TextureFile file;
  GLuint shown = 0;
  if (current.rfind(kBuiltinTexturePrefix, 0) != 0 && checkTextureSource(current, graphDir, &file).empty())
    shown = textureThumbnails().get(file.realPath);
  if (shown) {
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(shown)), ImVec2(32, 32), ImVec2(0, 1), ImVec2(1, 0));
    ImGui::SameLine();
  }
  std::string label = "option " + option;
  if (ImGui::BeginCombo(label.c_str(), current.c_str())) {
    if (ImGui::IsWindowAppearing()) listedTextures() = listGraphTextures(graphDir);
    auto choose = [&](const std::string& source) {
      noteRefusal(nodeId, chooseTexture(editor, registry, graphDir, nodeId, option, source));
    };
    for (const std::string& builtin : builtinTextureNames()) {
      std::string source = std::string(kBuiltinTexturePrefix) + builtin;
      if (ImGui::Selectable(source.c_str(), source == current)) choose(source);
    }
    const TextureChoices& listed = listedTextures();
    if (listed.paths.empty()) ImGui::TextDisabled("no PNG files under the graph's folder");
    for (const std::string& path : listed.paths) {
      ImGui::PushID(path.c_str());
      TextureFile f;
      if (checkTextureSource(path, graphDir, &f).empty())
        if (GLuint t = textureThumbnails().get(f.realPath)) {
          ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(t)), ImVec2(20, 20), ImVec2(0, 1), ImVec2(1, 0));
          ImGui::SameLine();
        }
      if (ImGui::Selectable(path.c_str(), path == current)) choose(path);
      noteItem("texture choice " + path);
      ImGui::PopID();
    }
    if (listed.truncated) ImGui::TextDisabled("(more files than shown: type the path in the file)");
    ImGui::EndCombo();
  }
  noteItem("texture picker " + option);
  if (authoringRefusal.node == nodeId && !authoringRefusal.text.empty())
    ImGui::TextColored(kRefusalColor, "%s", authoringRefusal.text.c_str());
}

namespace {
bool functionNameActive = false;  // the name field had the keyboard in the last frame
}  // namespace

bool newFunctionNameActive() { return functionNameActive; }

bool drawNewFunctionNode(GraphEditor& editor, const Registry& registry, std::array<double, 2> position, std::string* addedId) {
  static std::array<char, 65> name{};
  static std::string refusal;
  ImGui::SetNextItemWidth(150);
  bool enter = ImGui::InputTextWithHint("##function name", "function name", name.data(), name.size(), ImGuiInputTextFlags_EnterReturnsTrue);
  noteItem("new function name");
  functionNameActive = ImGui::IsItemActive();
  if (ImGui::IsItemEdited()) refusal.clear();
  ImGui::SameLine();
  bool pressed = ImGui::Button("new function node");
  noteItem("new function button");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("writes NAME.glsl beside the graph from a template and adds a glsl_function node calling it");
  bool added = false;
  if (pressed || enter) {
    std::string dir = std::filesystem::path(editor.graph().file).parent_path().string();
    refusal = addFunctionNodeFromTemplate(editor, registry, dir, name.data(), position, addedId);
    added = refusal.empty();
    if (added) name[0] = '\0';
  }
  if (!refusal.empty()) ImGui::TextColored(kRefusalColor, "%s", refusal.c_str());
  return added;
}

}  // namespace wg::editor
