#pragma once
// The node canvas: the graph drawn with ImGui draw lists (nodes, ports, links and the
// graph's output slots) and edited through the GraphEditor: select (click, Shift+click,
// drag a box on the background), move (drag a node: every selected one moves), connect
// (drag from an output port to an input port), disconnect (drag a link off its input, or
// right-click the input), add from the palette (right-click the background: the graph's
// subgraphs and the registry's types; right-click a link: the node goes into it), delete
// (Delete key; Ctrl+Delete reconnects pass-throughs), open a subgraph instance
// (double-click). The view zooms about the cursor (wheel, = and -), pans (middle or
// Alt+left drag), frames the selection (F) or everything (Home), and a minimap in the
// corner shows the whole graph (click or drag in it to move there). Frames (titled,
// commented boxes around nodes, editor/canvas_frames.h) are drawn behind the nodes: Ctrl+G
// makes one around the selection, dragging its title bar moves its nodes, right-clicking
// the title bar opens its menu. A function graph's
// interface outputs are shown, read-only, under the output slots. Node positions are the
// file's "editor": {x, y}.
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/diagnostic.h"
#include "core/graph_edit.h"
#include "core/registry.h"
#include "editor/canvas_frames.h"
#include "editor/canvas_view.h"
#include "editor/key_events.h"

struct ImVec2;
struct ImDrawList;

namespace wg::editor {

class NodeCanvas {
 public:
  // Draws into the current ImGui window, filling the rest of it. `selected` is the selected
  // node id ("" for none; the last one clicked of a selection) and may be changed.
  // `diagnostics` (the error list) are drawn on their nodes: an error outlines the node in
  // red; a warning on an input (a half-wired node's required input) marks it in orange.
  // `keys` are the frame's key presses (editor/key_events.h).
  void draw(GraphEditor& editor, const Registry& registry, std::string& selected,
            const std::vector<Diagnostic>& diagnostics = {}, const std::vector<KeyPress>& keys = {});
  // The instance node double-clicked since the last call ("" for none): the app opens
  // its subgraph between frames.
  std::string takeOpenRequest() { return std::exchange(openRequest_, {}); }
  const std::vector<std::string>& selection() const { return selection_; }
  void select(std::vector<std::string> ids) { selection_ = std::move(ids); }
  // Where a paste lands: the canvas point under the pointer when it was over the canvas in
  // the last frame, else the middle of the view.
  std::array<double, 2> pasteAnchor() const { return pasteAnchor_; }

 private:
  struct Layout;  // this frame's boxes and ports, and hit tests on them
  Layout layout(const Graph& g, const Registry& registry, ImVec2 origin) const;
  void startDrag(const Layout& l, ImVec2 mouse, std::string& selected);
  void beginMove(const Layout& l);
  void rightClick(GraphEditor& editor, const Layout& l, ImVec2 mouse, ImVec2 origin, std::string& selected);
  void continueDrag(GraphEditor& editor, const Layout& l, ImVec2 mouse, ImVec2 origin, ImDrawList* dl);
  void finishDrag(GraphEditor& editor, const Layout& l, ImVec2 mouse, std::string& selected);
  void viewKeys(const Layout& l, ImVec2 mouse, ImVec2 origin, ImVec2 size, bool hovered, const std::vector<KeyPress>& keys);
  void drawLinks(const Layout& l, ImDrawList* dl) const;
  void noteLinks(const Layout& l) const;
  void drawBoxes(const Layout& l, ImDrawList* dl, const std::vector<Diagnostic>& diagnostics) const;
  void drawPalette(GraphEditor& editor, const Registry& registry, std::string& selected, const std::vector<KeyPress>& keys);
  bool isSelected(const std::string& id) const;

  enum class Drag { None, MoveNodes, Link, Pan, Box, Minimap };
  Drag drag_ = Drag::None;
  CanvasView view_;
  std::vector<std::string> selection_;  // every selected node, `selected` among them
  std::string lastSelected_;            // `selected` as the canvas left it: a change from outside resets the selection
  // MoveNodes: the nodes and where they started; Link: the source output and, when an
  // existing link was picked up from an input, that input; Box: where the drag started
  // (panel pixels).
  std::vector<std::pair<std::string, std::array<double, 2>>> moveStarts_;
  std::string linkFromNode_, linkFromPort_;
  InputTarget detached_;
  bool hasDetached_ = false;
  std::array<float, 2> boxStart_{};   // screen pixels
  bool boxAdds_ = false;                // Shift held: the box adds to the selection
  std::array<double, 2> paletteAt_{};   // canvas position for a node added from the palette
  std::optional<InputTarget> insertInto_;  // the link the palette was opened on: the node goes into it
  char filter_[64] = "";
  std::string shownFilter_;  // the filter paletteIndex_ is for
  int paletteIndex_ = 0;     // the highlighted entry: Enter adds it, the arrows move it
  std::string openRequest_;
  std::array<double, 2> pasteAnchor_{};
  FrameMenu frameMenu_;
};

}  // namespace wg::editor
