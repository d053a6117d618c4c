#include "editor/canvas_minimap.h"

#include <algorithm>

namespace wg::editor {

std::optional<Minimap> Minimap::place(ImVec2 origin, ImVec2 size, const std::optional<CanvasRect>& graph,
                                      const CanvasView& view) {
  constexpr float kWidth = 180, kHeight = 110, kInset = 8;
  if (!graph || size.x < kWidth * 2.5f || size.y < kHeight * 1.8f) return std::nullopt;
  Minimap m;
  m.max_ = ImVec2(origin.x + size.x - kInset, origin.y + size.y - kInset);
  m.min_ = ImVec2(m.max_.x - kWidth, m.max_.y - kHeight);
  auto a = view.toCanvas(0, 0), b = view.toCanvas(size.x, size.y);
  m.viewArea_ = {a[0], a[1], b[0], b[1]};
  m.world_ = *enclosing(graph, m.viewArea_);
  double w = std::max(m.world_.x1 - m.world_.x0, 1.0), h = std::max(m.world_.y1 - m.world_.y0, 1.0);
  m.scale_ = std::min((kWidth - 8) / w, (kHeight - 8) / h);
  // Centred in the minimap's box.
  double cx = (m.world_.x0 + m.world_.x1) / 2, cy = (m.world_.y0 + m.world_.y1) / 2;
  double halfW = (kWidth - 8) / 2 / m.scale_, halfH = (kHeight - 8) / 2 / m.scale_;
  m.world_ = {cx - halfW, cy - halfH, cx + halfW, cy + halfH};
  return m;
}

ImVec2 Minimap::toScreen(double x, double y) const {
  return ImVec2(static_cast<float>(min_.x + 4 + (x - world_.x0) * scale_), static_cast<float>(min_.y + 4 + (y - world_.y0) * scale_));
}

std::array<double, 2> Minimap::toCanvas(ImVec2 p) const {
  return {world_.x0 + (p.x - min_.x - 4) / scale_, world_.y0 + (p.y - min_.y - 4) / scale_};
}

void Minimap::draw(ImDrawList* dl, const std::vector<std::pair<CanvasRect, ImU32>>& boxes) const {
  dl->AddRectFilled(min_, max_, IM_COL32(18, 19, 24, 220), 4);
  dl->AddRect(min_, max_, IM_COL32(90, 95, 110, 255), 4);
  dl->PushClipRect(min_, max_, true);
  for (const auto& [r, color] : boxes) {
    ImVec2 a = toScreen(r.x0, r.y0), b = toScreen(r.x1, r.y1);
    dl->AddRectFilled(a, ImVec2(std::max(b.x, a.x + 2), std::max(b.y, a.y + 2)), color);
  }
  dl->AddRect(toScreen(viewArea_.x0, viewArea_.y0), toScreen(viewArea_.x1, viewArea_.y1), IM_COL32(255, 255, 255, 200), 0, 0, 1.5f);
  dl->PopClipRect();
}

}  // namespace wg::editor
