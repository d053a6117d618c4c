#include "editor/widget_rects.h"

namespace wg::editor {

WidgetRects& widgetRects() {
  static WidgetRects rects;
  return rects;
}

}  // namespace wg::editor
