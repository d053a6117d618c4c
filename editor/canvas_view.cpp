#include "editor/canvas_view.h"

#include <algorithm>
#include <cmath>

namespace wg::editor {

std::array<float, 2> CanvasView::toPanel(double x, double y) const {
  // Far-off nodes (positions up to float32's largest) land far off, never at infinity.
  auto far = [](double v) { return static_cast<float>(std::clamp(v, -1e7, 1e7)); };
  return {far(pan_[0] + x * zoom_), far(pan_[1] + y * zoom_)};
}

std::array<double, 2> CanvasView::toCanvas(float px, float py) const {
  return {(static_cast<double>(px) - pan_[0]) / zoom_, (static_cast<double>(py) - pan_[1]) / zoom_};
}

void CanvasView::zoomAbout(std::array<float, 2> at, float factor) {
  if (!(factor > 0) || !std::isfinite(factor)) return;
  std::array<double, 2> fixed = toCanvas(at[0], at[1]);
  zoom_ = std::clamp(zoom_ * factor, kMinZoom, kMaxZoom);
  pan_[0] = static_cast<float>(at[0] - fixed[0] * zoom_);
  pan_[1] = static_cast<float>(at[1] - fixed[1] * zoom_);
}

void CanvasView::frame(const CanvasRect& box, std::array<float, 2> panelSize) {
  constexpr float kMargin = 30;  // pixels left around the framed box
  double w = std::max(box.x1 - box.x0, 1.0), h = std::max(box.y1 - box.y0, 1.0);
  double fit = std::min((panelSize[0] - 2 * kMargin) / w, (panelSize[1] - 2 * kMargin) / h);
  zoom_ = std::clamp(static_cast<float>(fit), kMinZoom, kMaxZoom);
  double cx = (box.x0 + box.x1) / 2, cy = (box.y0 + box.y1) / 2;
  pan_[0] = static_cast<float>(panelSize[0] / 2 - cx * zoom_);
  pan_[1] = static_cast<float>(panelSize[1] / 2 - cy * zoom_);
}

std::optional<CanvasRect> enclosing(const std::optional<CanvasRect>& a, const CanvasRect& b) {
  if (!a) return b;
  return CanvasRect{std::min(a->x0, b.x0), std::min(a->y0, b.y0), std::max(a->x1, b.x1), std::max(a->y1, b.y1)};
}

}  // namespace wg::editor
