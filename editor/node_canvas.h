#pragma once
// The node canvas: the graph drawn with ImGui draw lists (nodes, ports, links and the
// graph's output slots) and edited through the GraphEditor: select, move, connect (drag
// from an output port to an input port), disconnect (drag a link off its input, or
// right-click the input), add from the palette (right-click the background: the graph's
// subgraphs and the registry's types), delete (Delete key), open a subgraph instance
// (double-click). A function graph's interface outputs are shown, read-only, under the
// output slots. Node positions are the file's "editor": {x, y}.
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "core/diagnostic.h"
#include "editor/key_events.h"

#include "core/graph_edit.h"
#include "core/registry.h"

struct ImVec2;
struct ImDrawList;

namespace wg::editor {

class NodeCanvas {
 public:
  // Draws into the current ImGui window, filling the rest of it. `selected` is the selected
  // node id ("" for none) and may be changed.
  // `diagnostics` (the error list) are drawn on their nodes: an error outlines the node in
  // red; a warning on an input (a half-wired node's required input) marks it in orange.
  // `keys` are the frame's key presses (editor/key_events.h): Delete, and Enter and the
  // arrows in the palette.
  void draw(GraphEditor& editor, const Registry& registry, std::string& selected,
            const std::vector<Diagnostic>& diagnostics = {}, const std::vector<KeyPress>& keys = {});
  // The instance node double-clicked since the last call ("" for none): the app opens
  // its subgraph between frames.
  std::string takeOpenRequest() { return std::exchange(openRequest_, {}); }

 private:
  struct Layout;  // this frame's boxes and ports, and hit tests on them
  Layout layout(const Graph& g, const Registry& registry, ImVec2 origin) const;
  void startDrag(const Layout& l, ImVec2 mouse, std::string& selected);
  void rightClick(GraphEditor& editor, const Layout& l, ImVec2 mouse, ImVec2 origin, std::string& selected);
  void continueDrag(GraphEditor& editor, const Layout& l, ImVec2 mouse, ImDrawList* dl);
  void finishDrag(GraphEditor& editor, const Layout& l, ImVec2 mouse);
  void drawLinks(const Layout& l, ImDrawList* dl) const;
  void drawBoxes(const Layout& l, ImDrawList* dl, const std::string& selected,
                 const std::vector<Diagnostic>& diagnostics) const;
  void drawPalette(GraphEditor& editor, const Registry& registry, std::string& selected, const std::vector<KeyPress>& keys);

  enum class Drag { None, MoveNode, Link, Pan };
  Drag drag_ = Drag::None;
  std::array<float, 2> scroll_{40, 40};  // canvas origin inside the window, in pixels
  // MoveNode: the node and where it started; Link: the source output and, when an existing
  // link was picked up from an input, that input.
  std::string dragNode_;
  std::array<double, 2> dragStart_{};
  std::string linkFromNode_, linkFromPort_;
  InputTarget detached_;
  bool hasDetached_ = false;
  std::array<float, 2> paletteAt_{};  // canvas position for a node added from the palette
  char filter_[64] = "";
  std::string shownFilter_;  // the filter paletteIndex_ is for
  int paletteIndex_ = 0;     // the highlighted entry: Enter adds it, the arrows move it
  std::string openRequest_;
};

}  // namespace wg::editor
