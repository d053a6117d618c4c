#include "editor/script_input.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cctype>
#include <fstream>
#include <map>

#include "editor/widget_rects.h"

namespace wg::editor {
namespace {

// The key names a script may use: letters, digits, and these.
int glfwKeyNamed(const std::string& name) {
  if (name.size() == 1 && std::isalpha(static_cast<unsigned char>(name[0])))
    return GLFW_KEY_A + (std::tolower(static_cast<unsigned char>(name[0])) - 'a');
  if (name.size() == 1 && std::isdigit(static_cast<unsigned char>(name[0]))) return GLFW_KEY_0 + (name[0] - '0');
  static const std::map<std::string, int> named{
      {"enter", GLFW_KEY_ENTER},   {"escape", GLFW_KEY_ESCAPE}, {"up", GLFW_KEY_UP},
      {"down", GLFW_KEY_DOWN},     {"left", GLFW_KEY_LEFT},     {"right", GLFW_KEY_RIGHT},
      {"delete", GLFW_KEY_DELETE}, {"backspace", GLFW_KEY_BACKSPACE}, {"tab", GLFW_KEY_TAB},
      {"space", GLFW_KEY_SPACE},   {"home", GLFW_KEY_HOME},     {"=", GLFW_KEY_EQUAL},
      {"-", GLFW_KEY_MINUS}};
  auto it = named.find(name);
  return it == named.end() ? GLFW_KEY_UNKNOWN : it->second;
}

int mouseButtonNamed(const std::string& name) {
  if (name == "left") return 0;
  if (name == "right") return 1;
  if (name == "middle") return 2;
  return -1;
}

// The callback GLFW would call now (the key queue, chained to ImGui's).
void deliverKey(GLFWwindow* w, int key, int action, int mods) {
  GLFWkeyfun cb = glfwSetKeyCallback(w, nullptr);
  glfwSetKeyCallback(w, cb);
  if (cb) cb(w, key, glfwGetKeyScancode(key), action, mods);
}

void deliverChar(GLFWwindow* w, unsigned codepoint) {
  GLFWcharfun cb = glfwSetCharCallback(w, nullptr);
  glfwSetCharCallback(w, cb);
  if (cb) cb(w, codepoint);
}

}  // namespace

std::string ScriptedInput::point(const nlohmann::json& step, const char* widgetKey, const char* atKey,
                                 std::array<float, 2>* out) const {
  if (step.contains(widgetKey)) {
    if (!step[widgetKey].is_string()) return std::string("\"") + widgetKey + "\" must be a widget's name";
    auto rect = widgetRects().find(step[widgetKey].get<std::string>());
    if (!rect) return "no widget '" + step[widgetKey].get<std::string>() + "' on screen (widgets are there once a frame is drawn)";
    std::array<double, 2> at{0.5, 0.5};
    if (step.contains(atKey)) {
      const auto& a = step[atKey];
      if (!a.is_array() || a.size() != 2 || !a[0].is_number() || !a[1].is_number())
        return std::string("\"") + atKey + "\" must be [fx, fy], fractions of the widget's box";
      at = {a[0].get<double>(), a[1].get<double>()};
    }
    const auto& r = *rect;
    *out = {static_cast<float>(r[0] + at[0] * (r[2] - r[0])), static_cast<float>(r[1] + at[1] * (r[3] - r[1]))};
    return "";
  }
  if (step.contains(atKey)) {
    const auto& a = step[atKey];
    if (!a.is_array() || a.size() != 2 || !a[0].is_number() || !a[1].is_number())
      return std::string("\"") + atKey + "\" must be [x, y] in window pixels";
    *out = {a[0].get<float>(), a[1].get<float>()};
    return "";
  }
  return std::string("needs \"") + widgetKey + "\" (a widget's name) or \"" + atKey + "\" (window pixels)";
}

std::string ScriptedInput::key(const nlohmann::json& step) {
  if (!step.contains("key") || !step["key"].is_string()) return "needs a string \"key\"";
  int key = glfwKeyNamed(step["key"].get<std::string>());
  if (key == GLFW_KEY_UNKNOWN) return "unknown key '" + step["key"].get<std::string>() + "'";
  int mods = (step.value("ctrl", false) ? GLFW_MOD_CONTROL : 0) | (step.value("shift", false) ? GLFW_MOD_SHIFT : 0);
  // A tap: modifiers down, the key down and up, modifiers up, all before the next frame.
  if (mods & GLFW_MOD_CONTROL) deliverKey(window_, GLFW_KEY_LEFT_CONTROL, GLFW_PRESS, mods);
  if (mods & GLFW_MOD_SHIFT) deliverKey(window_, GLFW_KEY_LEFT_SHIFT, GLFW_PRESS, mods);
  deliverKey(window_, key, GLFW_PRESS, mods);
  deliverKey(window_, key, GLFW_RELEASE, mods);
  if (mods & GLFW_MOD_SHIFT) deliverKey(window_, GLFW_KEY_LEFT_SHIFT, GLFW_RELEASE, mods & ~GLFW_MOD_SHIFT);
  if (mods & GLFW_MOD_CONTROL) deliverKey(window_, GLFW_KEY_LEFT_CONTROL, GLFW_RELEASE, 0);
  return "";
}

std::string ScriptedInput::type(const nlohmann::json& step) {
  if (!step.contains("text") || !step["text"].is_string()) return "needs a string \"text\"";
  for (unsigned char c : step["text"].get<std::string>()) {
    if (c < 0x20 || c > 0x7e) return "\"text\" is typed as printable ASCII only";
    deliverChar(window_, c);
  }
  return "";
}

std::string ScriptedInput::apply(const nlohmann::json& step) {
  const std::string op = step.value("op", "");
  if (op == "key") return key(step);
  if (op == "type") return type(step);
  int button = mouseButtonNamed(step.value("button", "left"));
  if (button < 0) return "\"button\" is left, right or middle";
  bool ctrl = step.value("ctrl", false);
  if (op == "click") {
    std::array<float, 2> at{};
    if (std::string why = point(step, "widget", "at", &at); !why.empty()) return why;
    // Down in one frame, up in the next: a click ImGui sees; twice for a double click.
    int clicks = step.value("double", false) ? 2 : 1;
    for (int i = 0; i < clicks; ++i) {
      frames_.push_back({at, button, 0, ctrl});
      frames_.push_back({at, -1, 0, ctrl});
    }
    rest_ = at;
    return "";
  }
  if (op == "drag") {
    std::array<float, 2> from{}, to{};
    if (std::string why = point(step, "widget", "from", &from); !why.empty()) return why;
    if (std::string why = point(step, "widget", "to", &to); !why.empty()) return why;
    constexpr int kSteps = 6;  // past ImGui's drag threshold in the first step
    frames_.push_back({from, button, 0, ctrl});
    for (int i = 1; i <= kSteps; ++i) {
      float t = static_cast<float>(i) / kSteps;
      frames_.push_back({{from[0] + t * (to[0] - from[0]), from[1] + t * (to[1] - from[1])}, button, 0, ctrl});
    }
    frames_.push_back({to, -1, 0, ctrl});
    rest_ = to;
    return "";
  }
  if (op == "set_clipboard") {
    if (!step.contains("text") || !step["text"].is_string()) return "needs a string \"text\"";
    glfwSetClipboardString(window_, step["text"].get<std::string>().c_str());
    return "";
  }
  if (op == "save_clipboard") {
    if (!step.contains("path") || !step["path"].is_string()) return "needs a string \"path\"";
    const char* text = glfwGetClipboardString(window_);
    std::ofstream out(step["path"].get<std::string>(), std::ios::binary | std::ios::trunc);
    out << (text ? text : "");
    return out ? "" : "cannot write " + step["path"].get<std::string>();
  }
  if (op == "hover") {
    std::array<float, 2> at{};
    if (std::string why = point(step, "widget", "at", &at); !why.empty()) return why;
    frames_.push_back({at, -1, 0, false});
    rest_ = at;
    return "";
  }
  if (op == "wheel") {
    std::array<float, 2> at{};
    if (std::string why = point(step, "widget", "at", &at); !why.empty()) return why;
    if (!step.contains("delta") || !step["delta"].is_number()) return "needs a number \"delta\" (wheel notches, + away)";
    frames_.push_back({at, -1, step["delta"].get<float>(), ctrl});
    rest_ = at;
    return "";
  }
  return "'" + op + "' is not an input step";
}

void ScriptedInput::overridePointer() {
  ImGuiIO& io = ImGui::GetIO();
  PointerFrame f{rest_, -1, 0, false};
  if (!frames_.empty()) f = frames_.front(), frames_.pop_front();
  io.MousePos = ImVec2(f.at[0], f.at[1]);
  for (int b = 0; b < 3; ++b) io.MouseDown[b] = b == f.button;
  io.MouseWheel += f.wheel;
  if (f.ctrl) io.KeyCtrl = true, ctrlHeld_ = true;
  else if (ctrlHeld_) io.KeyCtrl = false, ctrlHeld_ = false;
}

}  // namespace wg::editor
