#include "editor/panel_splitters.h"

#include <imgui.h>

#include <cmath>

#include "editor/widget_rects.h"

namespace wg::editor {
namespace {

constexpr float kGrip = 6;  // pixels: the handle's thickness

// One handle at (x, y, w, h); `fraction` moves by the drag over `extent` pixels along `vertical`
// (true: a vertical bar dragged sideways). True when its drag ended this frame.
bool splitter(const char* name, float x, float y, float w, float h, bool vertical, float extent, float* fraction) {
  ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(w, h), ImGuiCond_Always);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowMinSize, ImVec2(1, 1));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0);
  ImGui::Begin(name, nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoScrollWithMouse);
  ImGui::InvisibleButton("grip", ImVec2(w, h));
  bool active = ImGui::IsItemActive();
  bool ended = ImGui::IsItemDeactivated();
  if (active || ImGui::IsItemHovered()) {
    ImGui::SetMouseCursor(vertical ? ImGuiMouseCursor_ResizeEW : ImGuiMouseCursor_ResizeNS);
    ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(x, y), ImVec2(x + w, y + h), IM_COL32(120, 170, 255, active ? 200 : 110));
  }
  if (active) {
    float d = vertical ? ImGui::GetIO().MouseDelta.x : ImGui::GetIO().MouseDelta.y;
    if (d != 0 && extent > 0) *fraction += d / extent;
  }
  widgetRects().note(name + 2, {x, y, x + w, y + h});  // "##splitter left" -> "splitter left"
  ImGui::End();
  ImGui::PopStyleVar(3);
  return ended;
}

}  // namespace

bool drawPanelSplitters(PanelLayout& layout, float w, float h) {
  float left = std::floor(w * layout.leftWidth);
  bool ended = false;
  ended |= splitter("##splitter left", left - kGrip / 2, 0, kGrip, h, true, w, &layout.leftWidth);
  ended |= splitter("##splitter preview", 0, std::floor(h * layout.previewHeight) - kGrip / 2, left - kGrip / 2, kGrip, false, h,
                    &layout.previewHeight);
  ended |= splitter("##splitter inspector", left + kGrip / 2, std::floor(h * layout.inspectorHeight) - kGrip / 2,
                    w - left - kGrip / 2, kGrip, false, h, &layout.inspectorHeight);
  layout.clampToUsable();
  return ended;
}

}  // namespace wg::editor
