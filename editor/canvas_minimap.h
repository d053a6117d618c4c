#pragma once
// The node canvas's minimap: the whole graph, scaled down into the canvas's bottom right
// corner, with the part in view outlined. Clicking or dragging in it centres the view there.
#include <imgui.h>

#include <array>
#include <optional>
#include <vector>

#include "editor/canvas_view.h"

namespace wg::editor {

class Minimap {
 public:
  // Where the minimap goes in a canvas panel at `origin` of `size`, showing `graph` (every
  // node's box) and what the view shows; none when the panel is too small for one.
  static std::optional<Minimap> place(ImVec2 origin, ImVec2 size, const std::optional<CanvasRect>& graph,
                                      const CanvasView& view);

  std::array<float, 4> rect() const { return {min_.x, min_.y, max_.x, max_.y}; }
  bool contains(ImVec2 p) const { return p.x >= min_.x && p.x <= max_.x && p.y >= min_.y && p.y <= max_.y; }
  std::array<double, 2> toCanvas(ImVec2 p) const;
  // Boxes (canvas coordinates, their colours), then the view's outline.
  void draw(ImDrawList* dl, const std::vector<std::pair<CanvasRect, ImU32>>& boxes) const;

 private:
  ImVec2 toScreen(double x, double y) const;
  ImVec2 min_, max_;
  CanvasRect world_;     // the canvas area shown: the graph and the view
  CanvasRect viewArea_;  // what the canvas panel shows
  double scale_ = 1;     // minimap pixels per canvas unit
};

}  // namespace wg::editor
