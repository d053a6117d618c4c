#pragma once
// Where the node canvas looks: the pan (the screen offset of the canvas origin inside the
// canvas panel) and the zoom, and the arithmetic between canvas and panel coordinates.
// Zooming keeps the canvas point under the cursor where it is; framing fits a box of canvas
// coordinates (the selection, or every node) into the panel. No drawing: tested directly.
#include <array>
#include <optional>

namespace wg::editor {

// A box in canvas coordinates (a node's file position and size).
struct CanvasRect {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

class CanvasView {
 public:
  // Readable from 25 % (titles only) to 200 %.
  static constexpr float kMinZoom = 0.25f, kMaxZoom = 2.0f;

  float zoom() const { return zoom_; }
  const std::array<float, 2>& pan() const { return pan_; }

  // Panel pixel (relative to the panel's top left) <-> canvas coordinates.
  std::array<float, 2> toPanel(double x, double y) const;
  std::array<double, 2> toCanvas(float px, float py) const;

  void panBy(float dx, float dy) { pan_[0] += dx, pan_[1] += dy; }
  // Multiplies the zoom by `factor` (clamped to the range) about panel point `at`.
  void zoomAbout(std::array<float, 2> at, float factor);
  // Zoom and pan so that `box` fills the panel of `panelSize` with a margin, centred; the
  // zoom clamped to the range (a single small node is not blown up past 200 %).
  void frame(const CanvasRect& box, std::array<float, 2> panelSize);

 private:
  std::array<float, 2> pan_{40, 40};
  float zoom_ = 1;
};

// The smallest box holding `a` (when there is one) and `b`.
std::optional<CanvasRect> enclosing(const std::optional<CanvasRect>& a, const CanvasRect& b);

}  // namespace wg::editor
