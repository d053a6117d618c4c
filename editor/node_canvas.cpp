#include "editor/node_canvas.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <vector>

#include "core/graph_node_type.h"
#include "core/number_format.h"
#include "editor/authoring_widgets.h"
#include "editor/canvas_frames.h"
#include "editor/canvas_minimap.h"
#include "editor/dissolve_nodes.h"
#include "editor/function_node_ports.h"
#include "editor/link_insert.h"
#include "editor/node_palette.h"
#include "editor/widget_rects.h"

namespace wg::editor {
namespace {

constexpr float kNodeWidth = 180, kHeader = 22, kRow = 18, kPortRadius = 5;
constexpr ImU32 kWarningColor = IM_COL32(255, 160, 60, 255);  // a half-wired node's required inputs
constexpr ImU32 kErrorColor = IM_COL32(235, 80, 70, 255);

// The graph's output slots (outputSlotTable()) are drawn as one more node right of the others.
constexpr const char* kOutputsId = "";  // the pseudo node's id in InputTarget terms
// A function graph's interface outputs, shown under the output slots. Read-only: the edit
// model does not change the interface (it is edited in the file), so nothing links to it.
// Not an identifier, so never a node's id.
constexpr const char* kInterfaceId = "#interface";

struct Port {
  std::string name;
  ImVec2 at;
};

struct Box {
  std::string id;  // "" for the outputs pseudo node
  std::string title;
  CanvasRect area;  // in canvas coordinates
  ImVec2 min, max;  // on screen
  std::vector<Port> inputs, outputs;
  std::vector<std::string> inputNotes;  // per input: "$param", a constant, or ""
  bool instance = false;                // a subgraph instance: its own header colour
};

std::string sourceNote(const InputSource& s) {
  switch (s.kind) {
    case InputSource::Kind::Parameter: return "$" + s.name;
    case InputSource::Kind::Literal: {
      std::string t;
      for (size_t i = 0; i < s.literal.size(); ++i) t += (i ? ", " : "") + formatNumber(s.literal[i]);
      return s.literal.size() > 1 ? "(" + t + ")" : t;
    }
    case InputSource::Kind::NodeOutput: return "";
  }
  return "";
}

const InputSource* findInput(const Node& n, const std::string& port) {
  for (const auto& in : n.inputs)
    if (in.port == port) return &in.source;
  return nullptr;
}

const InputSource* findSlot(const Graph& g, OutputSlot slot) {
  for (const auto& o : g.outputs)
    if (o.slot == slot) return &o.source;
  return nullptr;
}

float distance(ImVec2 a, ImVec2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

float linkBend(ImVec2 from, ImVec2 to, float zoom) { return std::max(40.0f * zoom, std::abs(to.x - from.x) * 0.5f); }

void drawLink(ImDrawList* dl, ImVec2 from, ImVec2 to, ImU32 color, float zoom) {
  float dx = linkBend(from, to, zoom);
  dl->AddBezierCubic(from, ImVec2(from.x + dx, from.y), ImVec2(to.x - dx, to.y), to, color, std::max(1.5f, 2.5f * zoom));
}

// A point of the link's curve as drawLink draws it (t from 0 at the output to 1).
ImVec2 pointOnLink(ImVec2 from, ImVec2 to, float zoom, float t) {
  float dx = linkBend(from, to, zoom), u = 1 - t;
  float a = u * u * u, b = 3 * u * u * t, c = 3 * u * t * t, d = t * t * t;
  return ImVec2(a * from.x + b * (from.x + dx) + c * (to.x - dx) + d * to.x, a * from.y + b * from.y + c * to.y + d * to.y);
}

// How close `m` comes to the link's curve, sampled finely enough for a 6-pixel reach.
float distanceToLink(ImVec2 from, ImVec2 to, float zoom, ImVec2 m) {
  float best = distance(from, m);
  for (int i = 1; i <= 48; ++i) best = std::min(best, distance(pointOnLink(from, to, zoom, static_cast<float>(i) / 48), m));
  return best;
}

// Text at the view's zoom. Below kSmallestText pixels it is not drawn (port labels at 25 %
// would be specks); a title is never smaller than that, so every node stays readable.
constexpr float kSmallestText = 10;

void drawZoomedText(ImDrawList* dl, ImVec2 at, ImU32 color, const std::string& text, float pixels, const ImVec4& clip) {
  dl->AddText(ImGui::GetFont(), pixels, at, color, text.c_str(), nullptr, 0.0f, &clip);
}

void drawGrid(ImDrawList* dl, ImVec2 origin, ImVec2 size, const CanvasView& view) {
  dl->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), IM_COL32(30, 32, 38, 255));
  float step = 40 * view.zoom();
  if (step < 8) step *= 4;  // zoomed far out: a coarser grid, not a grey wash
  for (float x = std::fmod(view.pan()[0], step); x < size.x; x += step)
    dl->AddLine(ImVec2(origin.x + x, origin.y), ImVec2(origin.x + x, origin.y + size.y), IM_COL32(45, 48, 56, 255));
  for (float y = std::fmod(view.pan()[1], step); y < size.y; y += step)
    dl->AddLine(ImVec2(origin.x, origin.y + y), ImVec2(origin.x + size.x, origin.y + y), IM_COL32(45, 48, 56, 255));
}

}  // namespace

// The boxes of one frame, in screen coordinates, and the hit tests on them.
struct NodeCanvas::Layout {
  const Graph& g;
  std::vector<Box> boxes;
  float zoom = 1;
  std::vector<FrameBox> frames;  // behind the boxes (editor/canvas_frames.h)
  float portReach() const { return std::max(kPortRadius * zoom, 3.0f) + 4; }

  const Box* boxOf(const std::string& id) const {
    for (const auto& b : boxes)
      if (b.id == id) return &b;
    return nullptr;
  }
  std::optional<ImVec2> outputPort(const std::string& node, const std::string& port) const {
    const Box* b = node.empty() ? nullptr : boxOf(node);
    if (!b) return std::nullopt;
    for (const auto& p : b->outputs)
      if (p.name == port) return p.at;
    return std::nullopt;
  }
  // Hit tests: ports within a few pixels, then node boxes (topmost = last drawn).
  std::optional<InputTarget> inputAt(ImVec2 m) const {
    for (const auto& b : boxes)
      for (const auto& p : b.inputs)
        if (b.id != kInterfaceId && distance(p.at, m) <= portReach()) return InputTarget{b.id, p.name};
    return std::nullopt;
  }
  std::optional<std::pair<std::string, std::string>> outputAt(ImVec2 m) const {
    for (const auto& b : boxes)
      for (const auto& p : b.outputs)
        if (distance(p.at, m) <= portReach()) return std::make_pair(b.id, p.name);
    return std::nullopt;
  }
  // The link under `m` (a node output feeding a node input or an output slot), named by the
  // input it feeds: right-clicking one inserts a node into it (editor/link_insert.h).
  std::optional<InputTarget> linkAt(ImVec2 m) const {
    for (const auto& b : boxes)
      for (const auto& p : b.inputs) {
        const InputSource* s = b.id == kInterfaceId ? nullptr : sourceOf({b.id, p.name});
        if (!s || s->kind != InputSource::Kind::NodeOutput) continue;
        if (auto from = outputPort(s->name, s->port); from && distanceToLink(*from, p.at, zoom, m) <= 6) return InputTarget{b.id, p.name};
      }
    return std::nullopt;
  }
  const Box* nodeAt(ImVec2 m) const {
    for (auto it = boxes.rbegin(); it != boxes.rend(); ++it)
      if (!it->id.empty() && it->id != kInterfaceId && m.x >= it->min.x && m.x <= it->max.x && m.y >= it->min.y && m.y <= it->max.y) return &*it;
    return nullptr;
  }
  const InputSource* sourceOf(const InputTarget& t) const {
    if (t.node == kInterfaceId && g.interface) {
      for (const auto& o : g.interface->outputs)
        if (o.name == t.port) return &o.source;
      return nullptr;
    }
    if (t.node.empty()) {
      auto slot = parseOutputSlot(t.port);
      return slot ? findSlot(g, *slot) : nullptr;
    }
    const Node* n = g.findNode(t.node);
    return n ? findInput(*n, t.port) : nullptr;
  }
};

NodeCanvas::Layout NodeCanvas::layout(const Graph& g, const Registry& registry, ImVec2 origin) const {
  const float z = view_.zoom();
  Layout l{g, {}, z};
  // Canvas box -> screen box; ports at their rows.
  auto place = [&](Box& b, double x, double y, size_t rows) {
    b.area = {x, y, x + kNodeWidth, y + kHeader + kRow * static_cast<double>(rows) + 4};
    auto a = view_.toPanel(b.area.x0, b.area.y0), c = view_.toPanel(b.area.x1, b.area.y1);
    b.min = ImVec2(origin.x + a[0], origin.y + a[1]);
    b.max = ImVec2(origin.x + c[0], origin.y + c[1]);
  };
  auto rowY = [&](const Box& b, size_t i) { return b.min.y + (kHeader + kRow * (static_cast<float>(i) + 0.5f)) * z; };
  double rightmost = 0, top = 0;
  bool first = true;
  for (const auto& n : g.nodes) {
    std::array<double, 2> p = n.editorPosition.value_or(std::array<double, 2>{0, 0});
    rightmost = first ? p[0] : std::max(rightmost, p[0]);
    top = first ? p[1] : std::min(top, p[1]);
    first = false;
    Box b;
    b.id = n.id;
    b.title = n.id + " : " + n.type;
    b.instance = nodeTypeOf(g, registry, n.type).isInstance();
    std::vector<std::string> ins, outs;
    if (auto ports = editorPortsOf(g, registry, n)) {
      for (const auto& port : ports->inputs) ins.push_back(port.name);
      for (const auto& port : ports->outputs) outs.push_back(port.name);
    } else {
      for (const auto& in : n.inputs) ins.push_back(in.port);
    }
    place(b, p[0], p[1], std::max<size_t>(std::max(ins.size(), outs.size()), 1));
    for (size_t i = 0; i < ins.size(); ++i) {
      b.inputs.push_back({ins[i], ImVec2(b.min.x, rowY(b, i))});
      const InputSource* s = findInput(n, ins[i]);
      b.inputNotes.push_back(s ? sourceNote(*s) : "");
    }
    for (size_t i = 0; i < outs.size(); ++i) b.outputs.push_back({outs[i], ImVec2(b.max.x, rowY(b, i))});
    l.boxes.push_back(std::move(b));
  }
  Box b;
  b.id = kOutputsId;
  b.title = "outputs";
  const auto slots = outputSlotTable();
  place(b, rightmost + 260, top, slots.size());
  for (size_t i = 0; i < slots.size(); ++i) {
    b.inputs.push_back({std::string(slots[i].name), ImVec2(b.min.x, rowY(b, i))});
    const InputSource* s = findSlot(g, slots[i].id);
    b.inputNotes.push_back(s ? sourceNote(*s) : "");
  }
  double below = b.area.y1 + 20;
  l.boxes.push_back(std::move(b));
  if (g.interface) {
    Box in;
    in.id = kInterfaceId;
    in.title = "interface (edit in the file)";
    place(in, rightmost + 260, below, std::max<size_t>(g.interface->outputs.size(), 1));
    for (size_t i = 0; i < g.interface->outputs.size(); ++i) {
      const InterfaceOutput& o = g.interface->outputs[i];
      in.inputs.push_back({o.name, ImVec2(in.min.x, rowY(in, i))});
      in.inputNotes.push_back(sourceNote(o.source));
    }
    l.boxes.push_back(std::move(in));
  }
  auto nodeArea = [&](const std::string& id) { const Box* b = id.empty() ? nullptr : l.boxOf(id); return b ? std::optional(b->area) : std::nullopt; };
  l.frames = placeFrames(g, nodeArea, view_, origin, ImGui::GetFontSize());
  return l;
}

bool NodeCanvas::isSelected(const std::string& id) const {
  return std::find(selection_.begin(), selection_.end(), id) != selection_.end();
}

// A drag of the selected nodes (a node's box, or a frame's title bar) starts.
void NodeCanvas::beginMove(const Layout& l) {
  drag_ = Drag::MoveNodes;
  moveStarts_.clear();
  for (const auto& id : selection_)
    if (const Node* n = l.g.findNode(id)) moveStarts_.push_back({id, n->editorPosition.value_or(std::array<double, 2>{0, 0})});
}

void NodeCanvas::startDrag(const Layout& l, ImVec2 mouse, std::string& selected) {
  ImGuiIO& io = ImGui::GetIO();
  if (auto out = l.outputAt(mouse)) {
    drag_ = Drag::Link;
    linkFromNode_ = out->first, linkFromPort_ = out->second;
    hasDetached_ = false;
  } else if (auto in = l.inputAt(mouse); in && l.sourceOf(*in) && l.sourceOf(*in)->kind == InputSource::Kind::NodeOutput) {
    // Picking a link up from its input: dropped elsewhere it is disconnected.
    const InputSource* s = l.sourceOf(*in);
    drag_ = Drag::Link;
    linkFromNode_ = s->name, linkFromPort_ = s->port;
    detached_ = *in;
    hasDetached_ = true;
  } else if (const Box* b = l.nodeAt(mouse)) {
    if (io.KeyShift && isSelected(b->id)) {  // Shift+click on a selected node: out of the selection
      std::erase(selection_, b->id);
      selected = selection_.empty() ? "" : selection_.back();
      return;
    }
    if (io.KeyShift) selection_.push_back(b->id);
    else if (!isSelected(b->id)) selection_ = {b->id};
    selected = b->id;
    beginMove(l);
  } else if (const FrameBox* f = io.KeyAlt ? nullptr : frameTitleAt(l.frames, mouse)) {
    // A frame's title bar: its nodes are selected and move with it, one undo step.
    selection_ = l.g.findFrame(f->id)->nodes;
    selected = selection_.back();
    beginMove(l);
  } else if (io.KeyAlt) {
    drag_ = Drag::Pan;
  } else {
    // A box drawn on the background selects what it touches (Shift: adds to the selection).
    drag_ = Drag::Box;
    boxStart_ = {mouse.x, mouse.y};
    boxAdds_ = io.KeyShift;
    if (!boxAdds_) selection_.clear(), selected.clear();
  }
}

// On a connected input, disconnect it; on a node, select it; on the background, the palette.
void NodeCanvas::rightClick(GraphEditor& editor, const Layout& l, ImVec2 mouse, ImVec2 origin, std::string& selected) {
  if (auto in = l.inputAt(mouse); in && l.sourceOf(*in)) {
    editor.disconnect(*in);
  } else if (const Box* b = l.nodeAt(mouse)) {
    selected = b->id;
    if (!isSelected(b->id)) selection_ = {b->id};
  } else if (const FrameBox* f = frameTitleAt(l.frames, mouse)) {
    frameMenu_.open(l.g, f->id);
    ImGui::OpenPopup(kFrameMenuPopup);
  } else {
    // On a link, the node chosen goes into it; elsewhere it is added unconnected.
    insertInto_ = l.linkAt(mouse);
    paletteAt_ = view_.toCanvas(mouse.x - origin.x, mouse.y - origin.y);
    filter_[0] = '\0';
    ImGui::OpenPopup("palette");
  }
}

void NodeCanvas::continueDrag(GraphEditor& editor, const Layout& l, ImVec2 mouse, ImVec2 origin, ImDrawList* dl) {
  ImGuiIO& io = ImGui::GetIO();
  if (drag_ == Drag::MoveNodes && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    ImVec2 d = ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.0f);
    // Whole canvas units: positions in the file stay short.
    std::vector<std::pair<std::string, std::array<double, 2>>> to;
    for (const auto& [id, start] : moveStarts_)
      to.push_back({id, {std::round(start[0] + d.x / view_.zoom()), std::round(start[1] + d.y / view_.zoom())}});
    editor.moveNodes(to);
  }
  if (drag_ == Drag::Pan && (ImGui::IsMouseDown(ImGuiMouseButton_Left) || ImGui::IsMouseDown(ImGuiMouseButton_Middle)))
    view_.panBy(io.MouseDelta.x, io.MouseDelta.y);
  if (drag_ == Drag::Link) {
    ImVec2 from = l.outputPort(linkFromNode_, linkFromPort_).value_or(mouse);
    drawLink(dl, from, mouse, IM_COL32(255, 220, 120, 255), l.zoom);
  }
  if (drag_ == Drag::Box) {
    ImVec2 a(boxStart_[0], boxStart_[1]);
    dl->AddRectFilled(ImVec2(std::min(a.x, mouse.x), std::min(a.y, mouse.y)), ImVec2(std::max(a.x, mouse.x), std::max(a.y, mouse.y)),
                      IM_COL32(120, 170, 255, 40));
    dl->AddRect(ImVec2(std::min(a.x, mouse.x), std::min(a.y, mouse.y)), ImVec2(std::max(a.x, mouse.x), std::max(a.y, mouse.y)),
                IM_COL32(120, 170, 255, 200));
  }
}

// Both buttons up: a link lands on an input (or, picked up from one, is dropped), a box
// selects, a move or pan ends; either way the edit's undo step closes.
void NodeCanvas::finishDrag(GraphEditor& editor, const Layout& l, ImVec2 mouse, std::string& selected) {
  if (drag_ == Drag::None || ImGui::IsMouseDown(ImGuiMouseButton_Left) || ImGui::IsMouseDown(ImGuiMouseButton_Middle))
    return;
  if (drag_ == Drag::Link) {
    if (auto in = l.inputAt(mouse)) {
      if (!(hasDetached_ && in->node == detached_.node && in->port == detached_.port)) {
        if (hasDetached_) editor.disconnect(detached_);
        editor.connect(linkFromNode_, linkFromPort_, *in);
      }
    } else if (hasDetached_) {
      editor.disconnect(detached_);
    }
  }
  if (drag_ == Drag::Box) {
    ImVec2 lo(std::min(boxStart_[0], mouse.x), std::min(boxStart_[1], mouse.y));
    ImVec2 hi(std::max(boxStart_[0], mouse.x), std::max(boxStart_[1], mouse.y));
    for (const Box& b : l.boxes) {
      bool touches = b.min.x <= hi.x && b.max.x >= lo.x && b.min.y <= hi.y && b.max.y >= lo.y;
      if (touches && l.g.findNode(b.id) && !isSelected(b.id)) selection_.push_back(b.id);
    }
    if (!selection_.empty()) selected = selection_.back();
  }
  editor.seal();
  drag_ = Drag::None;
}

// Zoom (= and -, about the pointer when it is over the canvas), frame the selection (F) or
// everything (Home): while the pointer is over the canvas and no text field has the keys.
void NodeCanvas::viewKeys(const Layout& l, ImVec2 mouse, ImVec2 origin, ImVec2 size, bool hovered,
                          const std::vector<KeyPress>& keys) {
  if (!hovered || ImGui::GetIO().WantTextInput) return;
  std::array<float, 2> at{mouse.x - origin.x, mouse.y - origin.y};
  for (const KeyPress& k : keys) {
    if (k.key == GLFW_KEY_EQUAL || k.key == GLFW_KEY_KP_ADD) view_.zoomAbout(at, 1.25f);
    if (k.key == GLFW_KEY_MINUS || k.key == GLFW_KEY_KP_SUBTRACT) view_.zoomAbout(at, 0.8f);
    if ((k.key == GLFW_KEY_F && !(k.mods & GLFW_MOD_CONTROL)) || k.key == GLFW_KEY_HOME) {
      std::optional<CanvasRect> box, all;
      for (const Box& b : l.boxes) {
        all = enclosing(all, b.area);
        if (isSelected(b.id)) box = enclosing(box, b.area);
      }
      for (const FrameBox& f : l.frames) all = enclosing(all, f.area);
      if (k.key == GLFW_KEY_HOME || !box) box = all;
      if (box) view_.frame(*box, {size.x, size.y});
    }
  }
}

// For scripts: each link's middle, as "link NODE.PORT" (an output slot: "link outputs.SLOT").
void NodeCanvas::noteLinks(const Layout& l) const {
  for (const auto& b : l.boxes)
    for (const auto& p : b.inputs) {
      const InputSource* s = b.id == kInterfaceId ? nullptr : l.sourceOf({b.id, p.name});
      auto from = s && s->kind == InputSource::Kind::NodeOutput ? l.outputPort(s->name, s->port) : std::nullopt;
      if (!from) continue;
      ImVec2 mid = pointOnLink(*from, p.at, l.zoom, 0.5f);
      widgetRects().note("link " + (b.id.empty() ? std::string("outputs") : b.id) + "." + p.name, {mid.x - 2, mid.y - 2, mid.x + 2, mid.y + 2});
    }
}

// Links under the boxes; a link being dragged off its input is drawn by continueDrag.
void NodeCanvas::drawLinks(const Layout& l, ImDrawList* dl) const {
  auto linkColor = IM_COL32(140, 200, 255, 220);
  for (const auto& b : l.boxes) {
    for (const auto& p : b.inputs) {
      const InputSource* s = l.sourceOf({b.id, p.name});
      if (!s || s->kind != InputSource::Kind::NodeOutput) continue;
      if (drag_ == Drag::Link && hasDetached_ && detached_.node == b.id && detached_.port == p.name) continue;
      if (auto from = l.outputPort(s->name, s->port)) drawLink(dl, *from, p.at, linkColor, l.zoom);
    }
  }
}

void NodeCanvas::drawBoxes(const Layout& l, ImDrawList* dl, const std::vector<Diagnostic>& diagnostics) const {
  const float z = l.zoom, fontPx = ImGui::GetFontSize();
  const float labelPx = fontPx * z;  // port labels: hidden when smaller than kSmallestText
  const float titlePx = std::max(fontPx * z, kSmallestText);
  const float radius = std::max(kPortRadius * z, 3.0f), rounding = 5 * z;
  for (const auto& b : l.boxes) {
    bool selectedBox = !b.id.empty() && isSelected(b.id);
    bool hasError = false, hasWarning = false;
    std::set<std::string> warnedInputs;  // "input 'color'", as diagnostics name ports
    for (const Diagnostic& d : diagnostics) {
      if (b.id.empty() || d.node != b.id) continue;
      if (d.severity == Severity::Error) hasError = true;
      if (d.severity == Severity::Warning) hasWarning = true, warnedInputs.insert(d.port);
    }
    if (l.g.findNode(b.id)) widgetRects().note("node " + b.id, {b.min.x, b.min.y, b.max.x, b.max.y});
    dl->AddRectFilled(b.min, b.max, IM_COL32(52, 56, 66, 240), rounding);
    ImU32 header = b.id.empty() || b.id == kInterfaceId ? IM_COL32(110, 70, 40, 255) : b.instance ? IM_COL32(60, 105, 70, 255) : IM_COL32(40, 80, 120, 255);
    dl->AddRectFilled(b.min, ImVec2(b.max.x, b.min.y + kHeader * z), header, rounding);
    ImU32 border = selectedBox ? IM_COL32(255, 220, 120, 255)
                   : hasError  ? kErrorColor
                   : hasWarning ? kWarningColor
                                : IM_COL32(90, 95, 110, 255);
    dl->AddRect(b.min, b.max, border, rounding, 0, selectedBox || hasError || hasWarning ? 2.5f : 1.0f);
    // Zoomed out, the id alone (the type does not fit); the title may overhang the header.
    std::string title = z < 0.6f ? b.id.empty() ? b.title : b.id : b.title;
    drawZoomedText(dl, ImVec2(b.min.x + 6 * z, b.min.y + 4 * z), IM_COL32(235, 235, 235, 255), title, titlePx,
                   ImVec4(b.min.x, b.min.y - titlePx, b.max.x, b.max.y));
    for (size_t i = 0; i < b.inputs.size(); ++i) {
      const Port& p = b.inputs[i];
      bool linked = !b.inputNotes[i].empty() || (l.sourceOf({b.id, p.name}) != nullptr);
      bool warned = warnedInputs.count("input '" + p.name + "'") > 0;
      dl->AddCircleFilled(p.at, radius, warned ? kWarningColor : linked ? IM_COL32(140, 200, 255, 255) : IM_COL32(120, 120, 130, 255));
      if (labelPx < kSmallestText) continue;
      std::string label = p.name + (b.inputNotes[i].empty() ? "" : " = " + b.inputNotes[i]) + (warned ? " (required)" : "");
      // Clipped to the box's left part: a long note (a subgraph instance's vec2 default)
      // must not run over the output labels on the right.
      bool sharesRow = i < b.outputs.size();
      ImVec4 clip(p.at.x + 9 * z, b.min.y, sharesRow ? b.min.x + kNodeWidth * 0.62f * z : b.max.x - 4, b.max.y);
      drawZoomedText(dl, ImVec2(p.at.x + 9 * z, p.at.y - labelPx / 2), warned ? kWarningColor : IM_COL32(210, 210, 210, 255),
                     label, labelPx, clip);
    }
    for (const auto& p : b.outputs) {
      dl->AddCircleFilled(p.at, radius, IM_COL32(255, 200, 120, 255));
      if (labelPx < kSmallestText) continue;
      float w = ImGui::GetFont()->CalcTextSizeA(labelPx, FLT_MAX, 0.0f, p.name.c_str()).x;
      drawZoomedText(dl, ImVec2(p.at.x - 9 * z - w, p.at.y - labelPx / 2), IM_COL32(210, 210, 210, 255), p.name, labelPx,
                     ImVec4(b.min.x, b.min.y, b.max.x, b.max.y));
    }
  }
}

// The graph's subgraphs and every registered node type (editor/node_palette.h), by family,
// filtered by name; the chosen one is added where the palette was opened. One entry is
// highlighted (the first of each new filter): Enter adds it, Up and Down move it.
void NodeCanvas::drawPalette(GraphEditor& editor, const Registry& registry, std::string& selected,
                             const std::vector<KeyPress>& keys) {
  if (!ImGui::BeginPopup("palette")) return;
  if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere(), paletteIndex_ = 0;
  ImGui::InputTextWithHint("##filter", "filter", filter_, sizeof filter_);
  if (frameSelectionEntry(editor, selection_)) ImGui::CloseCurrentPopup();
  if (insertInto_)
    ImGui::TextDisabled("into the link to %s.%s", insertInto_->node.empty() ? "outputs" : insertInto_->node.c_str(), insertInto_->port.c_str());
  const std::vector<PaletteEntry> entries = paletteEntries(editor.graph(), registry, filter_);
  if (shownFilter_ != filter_) shownFilter_ = filter_, paletteIndex_ = 0;
  const int count = static_cast<int>(entries.size());
  bool moved = false;
  for (const KeyPress& k : keys) {
    if (k.key == GLFW_KEY_DOWN && count > 0) paletteIndex_ = std::min(paletteIndex_ + 1, count - 1), moved = true;
    if (k.key == GLFW_KEY_UP && count > 0) paletteIndex_ = std::max(paletteIndex_ - 1, 0), moved = true;
  }
  const PaletteEntry* chosen = nullptr;
  if (count > 0 && !newFunctionNameActive() && (wasPressed(keys, GLFW_KEY_ENTER) || wasPressed(keys, GLFW_KEY_KP_ENTER))) chosen = &entries[static_cast<size_t>(paletteIndex_)];
  ImGui::BeginChild("types", ImVec2(260, 320));
  std::string family;
  for (int i = 0; i < count; ++i) {
    const PaletteEntry& e = entries[static_cast<size_t>(i)];
    if (e.family != family) ImGui::TextDisabled("%s", e.family.c_str());
    family = e.family;
    if (ImGui::Selectable(e.type.c_str(), i == paletteIndex_)) chosen = &e;
    if (i == paletteIndex_ && moved) ImGui::SetScrollHereY();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", e.summary.c_str());
  }
  ImGui::EndChild();
  ImGui::Separator();
  std::string made;
  if (drawNewFunctionNode(editor, registry, {std::round(paletteAt_[0]), std::round(paletteAt_[1])}, &made)) {
    selected = made, selection_ = {made};
    ImGui::CloseCurrentPopup();
  }
  if (chosen) {
    std::string id;
    std::array<double, 2> at{std::round(paletteAt_[0]), std::round(paletteAt_[1])};
    std::string why = insertInto_ ? insertNodeOnLink(editor, registry, chosen->type, *insertInto_, at, &id)
                                  : editor.addNode(chosen->type, "", at, &id);
    if (why.empty()) selected = id, selection_ = {id};
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

void NodeCanvas::draw(GraphEditor& editor, const Registry& registry, std::string& selected,
                      const std::vector<Diagnostic>& diagnostics, const std::vector<KeyPress>& keys) {
  ImGuiIO& io = ImGui::GetIO();
  // A selection made elsewhere (the error list, a script): that node alone.
  if (selected != lastSelected_ && !isSelected(selected)) selection_ = selected.empty() ? std::vector<std::string>{} : std::vector{selected};
  std::erase_if(selection_, [&](const std::string& id) { return !editor.graph().findNode(id); });
  ImVec2 origin = ImGui::GetCursorScreenPos();
  ImVec2 size = ImGui::GetContentRegionAvail();
  size.x = std::max(size.x, 50.0f), size.y = std::max(size.y, 50.0f);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
  drawGrid(dl, origin, size, view_);
  // The whole area is one invisible button: it takes the clicks ImGui would otherwise
  // give to the window (dragging it), and tells whether the mouse is over the canvas.
  ImGui::InvisibleButton("canvas", size, ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                                             ImGuiButtonFlags_MouseButtonMiddle);
  const bool hovered = ImGui::IsItemHovered();
  widgetRects().note("canvas", {origin.x, origin.y, origin.x + size.x, origin.y + size.y});
  const ImVec2 mouse = io.MousePos;
  pasteAnchor_ = hovered ? view_.toCanvas(mouse.x - origin.x, mouse.y - origin.y) : view_.toCanvas(size.x / 2, size.y / 2);

  Layout l = layout(editor.graph(), registry, origin);
  std::optional<CanvasRect> whole;
  for (const Box& b : l.boxes) whole = enclosing(whole, b.area);
  for (const FrameBox& f : l.frames) whole = enclosing(whole, f.area);
  std::optional<Minimap> minimap = Minimap::place(origin, size, whole, view_);
  auto centreOn = [&](std::array<double, 2> p) {  // the view's centre to canvas point p
    auto now = view_.toPanel(p[0], p[1]);
    view_.panBy(size.x / 2 - now[0], size.y / 2 - now[1]);
  };
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    if (minimap && minimap->contains(mouse)) drag_ = Drag::Minimap;
    else startDrag(l, mouse, selected);
  }
  if (drag_ == Drag::Minimap && minimap) {
    if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) centreOn(minimap->toCanvas(mouse));
    else drag_ = Drag::None;
  }
  if (const Box* b = hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left) ? l.nodeAt(mouse) : nullptr; b && b->instance)
    openRequest_ = b->id;
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Middle)) drag_ = Drag::Pan;
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Right)) rightClick(editor, l, mouse, origin, selected);
  continueDrag(editor, l, mouse, origin, dl);
  finishDrag(editor, l, mouse, selected);
  if (hovered && io.MouseWheel != 0) view_.zoomAbout({mouse.x - origin.x, mouse.y - origin.y}, std::pow(1.15f, io.MouseWheel));
  viewKeys(l, mouse, origin, size, hovered, keys);
  // Drawn as it is now: after this frame's zoom, pan and edits.
  Layout drawn = layout(editor.graph(), registry, origin);

  drawFrames(dl, drawn.g, drawn.frames, drawn.zoom, ImGui::GetFontSize(), selection_);
  drawLinks(drawn, dl);
  noteLinks(drawn);
  drawBoxes(drawn, dl, diagnostics);
  if (minimap) {
    minimap = Minimap::place(origin, size, whole, view_);
    std::vector<std::pair<CanvasRect, ImU32>> shown;
    for (const Box& b : drawn.boxes)
      shown.push_back({b.area, isSelected(b.id) ? IM_COL32(255, 220, 120, 255) : IM_COL32(110, 140, 190, 255)});
    if (minimap) minimap->draw(dl, shown), widgetRects().note("minimap", minimap->rect());
  }
  dl->PopClipRect();

  // Delete while the mouse is over the canvas: every selected node, one undo step; with Ctrl,
  // pass-throughs are reconnected (editor/dissolve_nodes.h).
  if (hovered && !selection_.empty() && !io.WantTextInput) {
    bool plain = wasPressed(keys, GLFW_KEY_DELETE) || wasPressed(keys, GLFW_KEY_BACKSPACE);
    bool reconnect = wasPressed(keys, GLFW_KEY_DELETE, GLFW_MOD_CONTROL) || wasPressed(keys, GLFW_KEY_BACKSPACE, GLFW_MOD_CONTROL);
    std::string why = reconnect ? dissolveNodes(editor, registry, selection_) : plain ? editor.deleteNodes(selection_) : "-";
    if (why.empty()) selection_.clear(), selected.clear();
    // Ctrl+G: a frame around the selection (its nodes leave other frames).
    if (wasPressed(keys, GLFW_KEY_G, GLFW_MOD_CONTROL)) frameAround(editor, selection_);
  }
  drawPalette(editor, registry, selected, keys);
  frameMenu_.draw(editor, selection_);
  lastSelected_ = selected;
}

}  // namespace wg::editor
