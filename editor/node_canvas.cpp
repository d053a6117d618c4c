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
  ImVec2 min, max;
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

void drawLink(ImDrawList* dl, ImVec2 from, ImVec2 to, ImU32 color) {
  float dx = std::max(40.0f, std::abs(to.x - from.x) * 0.5f);
  dl->AddBezierCubic(from, ImVec2(from.x + dx, from.y), ImVec2(to.x - dx, to.y), to, color, 2.5f);
}

void drawGrid(ImDrawList* dl, ImVec2 origin, ImVec2 size, const std::array<float, 2>& scroll) {
  dl->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), IM_COL32(30, 32, 38, 255));
  for (float x = std::fmod(scroll[0], 40.0f); x < size.x; x += 40)
    dl->AddLine(ImVec2(origin.x + x, origin.y), ImVec2(origin.x + x, origin.y + size.y), IM_COL32(45, 48, 56, 255));
  for (float y = std::fmod(scroll[1], 40.0f); y < size.y; y += 40)
    dl->AddLine(ImVec2(origin.x, origin.y + y), ImVec2(origin.x + size.x, origin.y + y), IM_COL32(45, 48, 56, 255));
}

}  // namespace

// The boxes of one frame, in screen coordinates, and the hit tests on them.
struct NodeCanvas::Layout {
  const Graph& g;
  std::vector<Box> boxes;

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
        if (b.id != kInterfaceId && distance(p.at, m) <= kPortRadius + 4) return InputTarget{b.id, p.name};
    return std::nullopt;
  }
  std::optional<std::pair<std::string, std::string>> outputAt(ImVec2 m) const {
    for (const auto& b : boxes)
      for (const auto& p : b.outputs)
        if (distance(p.at, m) <= kPortRadius + 4) return std::make_pair(b.id, p.name);
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
  // A position may be anything the file format allows (up to float32's largest): far-off
  // nodes are drawn at a far-off but finite place, never at an infinity ImGui cannot draw.
  auto toScreen = [&](double x, double y) {
    auto far = [](double v) { return static_cast<float>(std::clamp(v, -1e7, 1e7)); };
    return ImVec2(far(origin.x + scroll_[0] + x), far(origin.y + scroll_[1] + y));
  };
  Layout l{g, {}};
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
    if (auto ports = portsOfGraphNode(g, registry, n)) {
      for (const auto& port : ports->inputs) ins.push_back(port.name);
      for (const auto& port : ports->outputs) outs.push_back(port.name);
    } else {
      for (const auto& in : n.inputs) ins.push_back(in.port);
    }
    size_t rows = std::max<size_t>(std::max(ins.size(), outs.size()), 1);
    b.min = toScreen(p[0], p[1]);
    b.max = ImVec2(b.min.x + kNodeWidth, b.min.y + kHeader + kRow * static_cast<float>(rows) + 4);
    for (size_t i = 0; i < ins.size(); ++i) {
      b.inputs.push_back({ins[i], ImVec2(b.min.x, b.min.y + kHeader + kRow * (static_cast<float>(i) + 0.5f))});
      const InputSource* s = findInput(n, ins[i]);
      b.inputNotes.push_back(s ? sourceNote(*s) : "");
    }
    for (size_t i = 0; i < outs.size(); ++i)
      b.outputs.push_back({outs[i], ImVec2(b.max.x, b.min.y + kHeader + kRow * (static_cast<float>(i) + 0.5f))});
    l.boxes.push_back(std::move(b));
  }
  Box b;
  b.id = kOutputsId;
  b.title = "outputs";
  b.min = toScreen(rightmost + 260, top);
  const auto slots = outputSlotTable();
  b.max = ImVec2(b.min.x + kNodeWidth, b.min.y + kHeader + kRow * static_cast<float>(slots.size()) + 4);
  for (size_t i = 0; i < slots.size(); ++i) {
    b.inputs.push_back({std::string(slots[i].name), ImVec2(b.min.x, b.min.y + kHeader + kRow * (static_cast<float>(i) + 0.5f))});
    const InputSource* s = findSlot(g, slots[i].id);
    b.inputNotes.push_back(s ? sourceNote(*s) : "");
  }
  ImVec2 below(b.min.x, b.max.y + 20);
  l.boxes.push_back(std::move(b));
  if (g.interface) {
    Box in;
    in.id = kInterfaceId;
    in.title = "interface (edit in the file)";
    in.min = below;
    in.max = ImVec2(in.min.x + kNodeWidth, in.min.y + kHeader + kRow * static_cast<float>(std::max<size_t>(g.interface->outputs.size(), 1)) + 4);
    for (size_t i = 0; i < g.interface->outputs.size(); ++i) {
      const InterfaceOutput& o = g.interface->outputs[i];
      in.inputs.push_back({o.name, ImVec2(in.min.x, in.min.y + kHeader + kRow * (static_cast<float>(i) + 0.5f))});
      in.inputNotes.push_back(sourceNote(o.source));
    }
    l.boxes.push_back(std::move(in));
  }
  return l;
}

void NodeCanvas::startDrag(const Layout& l, ImVec2 mouse, std::string& selected) {
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
    selected = b->id;
    drag_ = Drag::MoveNode;
    dragNode_ = b->id;
    dragStart_ = l.g.findNode(b->id)->editorPosition.value_or(std::array<double, 2>{0, 0});
  } else {
    selected.clear();
    drag_ = Drag::Pan;
  }
}

// On a connected input, disconnect it; on a node, select it; on the background, the palette.
void NodeCanvas::rightClick(GraphEditor& editor, const Layout& l, ImVec2 mouse, ImVec2 origin, std::string& selected) {
  if (auto in = l.inputAt(mouse); in && l.sourceOf(*in)) {
    editor.disconnect(*in);
  } else if (const Box* b = l.nodeAt(mouse)) {
    selected = b->id;
  } else {
    paletteAt_ = {mouse.x - origin.x - scroll_[0], mouse.y - origin.y - scroll_[1]};
    filter_[0] = '\0';
    ImGui::OpenPopup("palette");
  }
}

void NodeCanvas::continueDrag(GraphEditor& editor, const Layout& l, ImVec2 mouse, ImDrawList* dl) {
  ImGuiIO& io = ImGui::GetIO();
  if (drag_ == Drag::MoveNode && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    ImVec2 d = ImGui::GetMouseDragDelta(ImGuiMouseButton_Left, 0.0f);
    // Whole pixels: positions in the file stay short.
    editor.moveNode(dragNode_, {std::round(dragStart_[0] + d.x), std::round(dragStart_[1] + d.y)});
  }
  if (drag_ == Drag::Pan && (ImGui::IsMouseDown(ImGuiMouseButton_Left) || ImGui::IsMouseDown(ImGuiMouseButton_Middle))) {
    scroll_[0] += io.MouseDelta.x;
    scroll_[1] += io.MouseDelta.y;
  }
  if (drag_ == Drag::Link) {
    ImVec2 from = l.outputPort(linkFromNode_, linkFromPort_).value_or(mouse);
    drawLink(dl, from, mouse, IM_COL32(255, 220, 120, 255));
  }
}

// Both buttons up: a link lands on an input (or, picked up from one, is dropped), a move
// or pan ends; either way the edit's undo step closes.
void NodeCanvas::finishDrag(GraphEditor& editor, const Layout& l, ImVec2 mouse) {
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
  editor.seal();
  drag_ = Drag::None;
}

// Links under the boxes; a link being dragged off its input is drawn by continueDrag.
void NodeCanvas::drawLinks(const Layout& l, ImDrawList* dl) const {
  auto linkColor = IM_COL32(140, 200, 255, 220);
  for (const auto& b : l.boxes) {
    for (const auto& p : b.inputs) {
      const InputSource* s = l.sourceOf({b.id, p.name});
      if (!s || s->kind != InputSource::Kind::NodeOutput) continue;
      if (drag_ == Drag::Link && hasDetached_ && detached_.node == b.id && detached_.port == p.name) continue;
      if (auto from = l.outputPort(s->name, s->port)) drawLink(dl, *from, p.at, linkColor);
    }
  }
}

void NodeCanvas::drawBoxes(const Layout& l, ImDrawList* dl, const std::string& selected,
                           const std::vector<Diagnostic>& diagnostics) const {
  for (const auto& b : l.boxes) {
    bool isSelected = !b.id.empty() && b.id == selected;
    bool hasError = false, hasWarning = false;
    std::set<std::string> warnedInputs;  // "input 'color'", as diagnostics name ports
    for (const Diagnostic& d : diagnostics) {
      if (b.id.empty() || d.node != b.id) continue;
      if (d.severity == Severity::Error) hasError = true;
      if (d.severity == Severity::Warning) hasWarning = true, warnedInputs.insert(d.port);
    }
    dl->AddRectFilled(b.min, b.max, IM_COL32(52, 56, 66, 240), 5);
    ImU32 header = b.id.empty() || b.id == kInterfaceId ? IM_COL32(110, 70, 40, 255) : b.instance ? IM_COL32(60, 105, 70, 255) : IM_COL32(40, 80, 120, 255);
    dl->AddRectFilled(b.min, ImVec2(b.max.x, b.min.y + kHeader), header, 5);
    ImU32 border = isSelected ? IM_COL32(255, 220, 120, 255)
                   : hasError ? kErrorColor
                   : hasWarning ? kWarningColor
                                : IM_COL32(90, 95, 110, 255);
    dl->AddRect(b.min, b.max, border, 5, 0, isSelected || hasError || hasWarning ? 2.5f : 1.0f);
    dl->AddText(ImVec2(b.min.x + 6, b.min.y + 4), IM_COL32(235, 235, 235, 255), b.title.c_str());
    for (size_t i = 0; i < b.inputs.size(); ++i) {
      const Port& p = b.inputs[i];
      bool linked = !b.inputNotes[i].empty() || (l.sourceOf({b.id, p.name}) != nullptr);
      bool warned = warnedInputs.count("input '" + p.name + "'") > 0;
      dl->AddCircleFilled(p.at, kPortRadius, warned ? kWarningColor : linked ? IM_COL32(140, 200, 255, 255) : IM_COL32(120, 120, 130, 255));
      std::string label = p.name + (b.inputNotes[i].empty() ? "" : " = " + b.inputNotes[i]) + (warned ? " (required)" : "");
      // Clipped to the box's left half: a long note (a subgraph instance's vec2 default)
      // must not run over the output labels on the right.
      bool sharesRow = i < b.outputs.size();
      ImVec4 clip(p.at.x + 9, b.min.y, sharesRow ? b.min.x + kNodeWidth * 0.62f : b.max.x - 4, b.max.y);
      dl->AddText(nullptr, 0.0f, ImVec2(p.at.x + 9, p.at.y - 7), warned ? kWarningColor : IM_COL32(210, 210, 210, 255),
                  label.c_str(), nullptr, 0.0f, &clip);
    }
    for (const auto& p : b.outputs) {
      dl->AddCircleFilled(p.at, kPortRadius, IM_COL32(255, 200, 120, 255));
      ImVec2 ts = ImGui::CalcTextSize(p.name.c_str());
      dl->AddText(ImVec2(p.at.x - 9 - ts.x, p.at.y - 7), IM_COL32(210, 210, 210, 255), p.name.c_str());
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
  const std::vector<PaletteEntry> entries = paletteEntries(editor.graph(), registry, filter_);
  if (shownFilter_ != filter_) shownFilter_ = filter_, paletteIndex_ = 0;
  const int count = static_cast<int>(entries.size());
  bool moved = false;
  for (const KeyPress& k : keys) {
    if (k.key == GLFW_KEY_DOWN && count > 0) paletteIndex_ = std::min(paletteIndex_ + 1, count - 1), moved = true;
    if (k.key == GLFW_KEY_UP && count > 0) paletteIndex_ = std::max(paletteIndex_ - 1, 0), moved = true;
  }
  const PaletteEntry* chosen = nullptr;
  if (count > 0 && (wasPressed(keys, GLFW_KEY_ENTER) || wasPressed(keys, GLFW_KEY_KP_ENTER))) chosen = &entries[static_cast<size_t>(paletteIndex_)];
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
  if (chosen) {
    std::string id;
    if (editor.addNode(chosen->type, "", {std::round(paletteAt_[0]), std::round(paletteAt_[1])}, &id).empty()) selected = id;
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

void NodeCanvas::draw(GraphEditor& editor, const Registry& registry, std::string& selected,
                      const std::vector<Diagnostic>& diagnostics, const std::vector<KeyPress>& keys) {
  ImGuiIO& io = ImGui::GetIO();
  ImVec2 origin = ImGui::GetCursorScreenPos();
  ImVec2 size = ImGui::GetContentRegionAvail();
  size.x = std::max(size.x, 50.0f), size.y = std::max(size.y, 50.0f);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
  drawGrid(dl, origin, size, scroll_);
  // The whole area is one invisible button: it takes the clicks ImGui would otherwise
  // give to the window (dragging it), and tells whether the mouse is over the canvas.
  ImGui::InvisibleButton("canvas", size, ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                                             ImGuiButtonFlags_MouseButtonMiddle);
  const bool hovered = ImGui::IsItemHovered();
  widgetRects().note("canvas", {origin.x, origin.y, origin.x + size.x, origin.y + size.y});
  const ImVec2 mouse = io.MousePos;

  Layout l = layout(editor.graph(), registry, origin);
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) startDrag(l, mouse, selected);
  if (const Box* b = hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left) ? l.nodeAt(mouse) : nullptr; b && b->instance)
    openRequest_ = b->id;
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Middle)) drag_ = Drag::Pan;
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Right)) rightClick(editor, l, mouse, origin, selected);
  continueDrag(editor, l, mouse, dl);
  finishDrag(editor, l, mouse);
  if (hovered && io.MouseWheel != 0) scroll_[1] += io.MouseWheel * 40;

  drawLinks(l, dl);
  drawBoxes(l, dl, selected, diagnostics);
  dl->PopClipRect();

  // Delete while the mouse is over the canvas.
  if (hovered && !selected.empty() && !io.WantTextInput &&
      (wasPressed(keys, GLFW_KEY_DELETE) || wasPressed(keys, GLFW_KEY_BACKSPACE))) {
    if (editor.deleteNode(selected).empty()) selected.clear();
  }
  drawPalette(editor, registry, selected, keys);
}

}  // namespace wg::editor
