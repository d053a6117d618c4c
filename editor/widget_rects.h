#pragma once
// Where named widgets were drawn in the last frame ("parameter max_depth", "canvas"), so
// that a script can point at one and click it as a person would (editor/script_input.h).
// One table for the process: there is one window, and the UI notes its widgets while it
// draws them.
#include <array>
#include <map>
#include <optional>
#include <string>

namespace wg::editor {

class WidgetRects {
 public:
  using Rect = std::array<float, 4>;  // x0, y0, x1, y1 in window pixels
  void note(const std::string& name, Rect r) { rects_[name] = r; }
  void clear() { rects_.clear(); }
  const std::map<std::string, Rect>& all() const { return rects_; }
  std::optional<Rect> find(const std::string& name) const {
    auto it = rects_.find(name);
    return it == rects_.end() ? std::nullopt : std::optional<Rect>(it->second);
  }

 private:
  std::map<std::string, Rect> rects_;
};

WidgetRects& widgetRects();

}  // namespace wg::editor
