#pragma once
// A script's keys and pointer (docs/editor.md, "Scripted mode"): what a person does, without
// a person. Keys go through the window's key and character callbacks, as GLFW delivers
// them (so a "tap" is a press and a release before the next frame: a quick tap on a slow
// frame); the pointer replaces the real one for ImGui, frame by frame, between the
// backend's new frame and ImGui's.
#include <array>
#include <deque>
#include <string>

#include <nlohmann/json.hpp>

struct GLFWwindow;

namespace wg::editor {

class ScriptedInput {
 public:
  explicit ScriptedInput(GLFWwindow* window) : window_(window) {}

  // Applies one step: "key", "type", "click", "drag" or "wheel". "" or why not.
  std::string apply(const nlohmann::json& step);
  // Pointer frames queued by a click or drag are still to come.
  bool busy() const { return !frames_.empty(); }
  // After the backend's new frame, before ImGui::NewFrame: this frame's scripted pointer.
  void overridePointer();

 private:
  struct PointerFrame {
    std::array<float, 2> at{};
    int button = -1;  // held in this frame (-1: none)
    float wheel = 0;
    bool ctrl = false;  // Ctrl held with it (a Ctrl+click)
  };
  std::string key(const nlohmann::json& step);
  std::string type(const nlohmann::json& step);
  // Where a step points: "widget" (a name in editor/widget_rects.h) with "at" as fractions
  // of its box (the centre by default), or "x", "y" in window pixels.
  std::string point(const nlohmann::json& step, const char* widgetKey, const char* atKey, std::array<float, 2>* out) const;

  GLFWwindow* window_;
  std::deque<PointerFrame> frames_;
  std::array<float, 2> rest_{-1e6f, -1e6f};  // where the pointer stays between steps
  bool ctrlHeld_ = false;                     // io.KeyCtrl set by the last frame
};

}  // namespace wg::editor
