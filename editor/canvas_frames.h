#pragma once
// The node canvas's frames (Frame in core/graph.h, the file's "editor": {"frames": ...}):
// boxes with a title bar and a comment, drawn behind the nodes around the nodes they hold.
// A frame's box follows its nodes (their bounding box, a margin, the comment above them and
// the title bar on top), so it has no size of its own to resize. Dragging the title bar
// moves the frame's nodes (the canvas does that as a node drag, one undo step); its
// right-click menu renames it, edits its comment, makes it hold the selected nodes, or
// deletes it (its nodes stay). Ctrl+G frames the selection.
#include <imgui.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/graph_edit.h"
#include "editor/canvas_view.h"

namespace wg::editor {

struct FrameBox {
  std::string id;
  CanvasRect area;     // canvas coordinates
  ImVec2 min, max;     // on screen
  float titleBottom;   // screen y where the title bar ends
};

// Where each frame of `g` is, around the canvas boxes `nodeArea` gives for its nodes (none
// for a node not drawn); a frame none of whose nodes is drawn is left out. `fontPx` is the
// canvas text size at 100 % (the comment's wrapped height is measured with it).
std::vector<FrameBox> placeFrames(const Graph& g, const std::function<std::optional<CanvasRect>(const std::string&)>& nodeArea,
                                  const CanvasView& view, ImVec2 origin, float fontPx);

// Draws the frames (in file order, the last on top) with their titles and comments; a frame
// whose nodes are all in `selection` is outlined. Notes "frame ID" (the title bar) for scripts.
void drawFrames(ImDrawList* dl, const Graph& g, const std::vector<FrameBox>& boxes, float zoom, float fontPx,
                const std::vector<std::string>& selection);

// The frame whose title bar is under `m` (the topmost), or none.
const FrameBox* frameTitleAt(const std::vector<FrameBox>& boxes, ImVec2 m);

// A new frame around `nodes` (Ctrl+G), titled by its id; "" or why not.
std::string frameAround(GraphEditor& editor, const std::vector<std::string>& nodes);

// The palette's entry "frame the N selected nodes (Ctrl+G)", shown while nodes are
// selected; true when clicked and the frame was made.
bool frameSelectionEntry(GraphEditor& editor, const std::vector<std::string>& selection);

// A frame's right-click menu: title and comment fields with `apply`, `hold the selection`,
// and `delete frame`. The canvas opens it (OpenPopup(kFrameMenuPopup)) and draws it.
inline constexpr const char* kFrameMenuPopup = "frame menu";
class FrameMenu {
 public:
  void open(const Graph& g, const std::string& id);
  void draw(GraphEditor& editor, const std::vector<std::string>& selection);

 private:
  std::string id_;
  char title_[256] = "";
  char comment_[4096] = "";
  std::string refusal_;
};

}  // namespace wg::editor
