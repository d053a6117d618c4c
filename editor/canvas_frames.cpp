#include "editor/canvas_frames.h"

#include <algorithm>
#include <cfloat>
#include <cstring>

#include "editor/widget_rects.h"

namespace wg::editor {
namespace {

// In canvas units (scaled by the zoom on screen).
constexpr double kFrameMargin = 18, kFrameTitleBar = 24, kCommentGap = 6;
// The smallest comment and title drawn, in pixels: zoomed out, a frame's text stays
// readable (its box grows to hold it) where port labels are left out.
constexpr float kFrameSmallestText = 10, kFrameSmallestTitle = 12;
constexpr ImU32 kFrameFill = IM_COL32(70, 90, 110, 70), kFrameTitleFill = IM_COL32(70, 90, 110, 170);
constexpr ImU32 kFrameBorder = IM_COL32(110, 135, 160, 200), kFrameSelected = IM_COL32(255, 220, 120, 255);

// The comment's text size on screen at `zoom`.
float commentPixels(float fontPx, float zoom) { return std::max(fontPx * zoom, kFrameSmallestText); }

float titlePixels(float fontPx, float zoom) { return std::max(fontPx * zoom * 1.15f, kFrameSmallestTitle); }

// The title bar's height in canvas units: its text with a margin, however far out the zoom.
double titleBarHeight(float fontPx, float zoom) { return std::max(kFrameTitleBar, static_cast<double>(titlePixels(fontPx, zoom) + 6) / zoom); }

// The comment's height in canvas units, wrapped to `width` canvas units, as drawn at `zoom`.
double commentHeight(const std::string& comment, double width, float fontPx, float zoom) {
  if (comment.empty()) return 0;
  ImVec2 size = ImGui::GetFont()->CalcTextSizeA(commentPixels(fontPx, zoom), FLT_MAX, static_cast<float>(width) * zoom, comment.c_str());
  return size.y / zoom + kCommentGap;
}

void noteFrameWidget(const char* name) {
  widgetRects().note(name, {ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y, ImGui::GetItemRectMax().x, ImGui::GetItemRectMax().y});
}

}  // namespace

std::vector<FrameBox> placeFrames(const Graph& g, const std::function<std::optional<CanvasRect>(const std::string&)>& nodeArea,
                                  const CanvasView& view, ImVec2 origin, float fontPx) {
  std::vector<FrameBox> out;
  for (const Frame& f : g.frames) {
    std::optional<CanvasRect> inner;
    for (const std::string& id : f.nodes)
      if (auto a = nodeArea(id)) inner = enclosing(inner, *a);
    if (!inner) continue;
    FrameBox b;
    b.id = f.id;
    double wrap = inner->x1 - inner->x0;
    b.area = {inner->x0 - kFrameMargin, inner->y0 - kFrameMargin - commentHeight(f.comment, wrap, fontPx, view.zoom()) - titleBarHeight(fontPx, view.zoom()),
              inner->x1 + kFrameMargin, inner->y1 + kFrameMargin};
    auto a = view.toPanel(b.area.x0, b.area.y0), c = view.toPanel(b.area.x1, b.area.y1);
    b.min = ImVec2(origin.x + a[0], origin.y + a[1]);
    b.max = ImVec2(origin.x + c[0], origin.y + c[1]);
    b.titleBottom = b.min.y + static_cast<float>(titleBarHeight(fontPx, view.zoom())) * view.zoom();
    out.push_back(std::move(b));
  }
  return out;
}

void drawFrames(ImDrawList* dl, const Graph& g, const std::vector<FrameBox>& boxes, float zoom, float fontPx,
                const std::vector<std::string>& selection) {
  const float rounding = 6 * zoom;
  for (const FrameBox& b : boxes) {
    const Frame* f = g.findFrame(b.id);
    if (!f) continue;
    bool selected = std::all_of(f->nodes.begin(), f->nodes.end(), [&](const std::string& id) {
      return std::find(selection.begin(), selection.end(), id) != selection.end();
    });
    dl->AddRectFilled(b.min, b.max, kFrameFill, rounding);
    dl->AddRectFilled(b.min, ImVec2(b.max.x, b.titleBottom), kFrameTitleFill, rounding);
    dl->AddRect(b.min, b.max, selected ? kFrameSelected : kFrameBorder, rounding, 0, selected ? 2.5f : 1.5f);
    widgetRects().note("frame " + b.id, {b.min.x, b.min.y, b.max.x, b.titleBottom});
    const float margin = static_cast<float>(kFrameMargin) * zoom;
    ImVec4 clip(b.min.x, b.min.y, b.max.x, b.max.y);
    // The title is never smaller than the smallest text, as a node's: a frame stays named at 25 %.
    const float titlePx = titlePixels(fontPx, zoom);
    const std::string& title = f->title.empty() ? f->id : f->title;
    dl->AddText(ImGui::GetFont(), titlePx, ImVec2(b.min.x + 8 * zoom, b.min.y + (b.titleBottom - b.min.y - titlePx) / 2),
                IM_COL32(240, 240, 240, 255), title.c_str(), nullptr, 0.0f, &clip);
    if (!f->comment.empty()) {
      float wrap = b.max.x - b.min.x - 2 * margin;  // the nodes' width, as placeFrames measured it
      dl->AddText(ImGui::GetFont(), commentPixels(fontPx, zoom), ImVec2(b.min.x + margin, b.titleBottom + 4 * zoom),
                  IM_COL32(215, 220, 200, 255), f->comment.c_str(), nullptr, wrap, &clip);
    }
  }
}

const FrameBox* frameTitleAt(const std::vector<FrameBox>& boxes, ImVec2 m) {
  for (auto it = boxes.rbegin(); it != boxes.rend(); ++it)
    if (m.x >= it->min.x && m.x <= it->max.x && m.y >= it->min.y && m.y <= it->titleBottom) return &*it;
  return nullptr;
}

std::string frameAround(GraphEditor& editor, const std::vector<std::string>& nodes) {
  Frame frame;
  frame.nodes = nodes;
  return editor.addFrame(std::move(frame));
}

bool frameSelectionEntry(GraphEditor& editor, const std::vector<std::string>& selection) {
  if (selection.empty()) return false;
  std::string label = "frame the " + std::to_string(selection.size()) + (selection.size() == 1 ? " selected node" : " selected nodes") + " (Ctrl+G)";
  bool clicked = ImGui::Selectable(label.c_str());
  noteFrameWidget("palette frame selection");
  return clicked && frameAround(editor, selection).empty();
}

void FrameMenu::open(const Graph& g, const std::string& id) {
  const Frame* f = g.findFrame(id);
  if (!f) return;
  id_ = id;
  std::snprintf(title_, sizeof title_, "%s", f->title.c_str());
  std::snprintf(comment_, sizeof comment_, "%s", f->comment.c_str());
  refusal_.clear();
}

void FrameMenu::draw(GraphEditor& editor, const std::vector<std::string>& selection) {
  if (!ImGui::BeginPopup(kFrameMenuPopup)) return;
  if (!editor.graph().findFrame(id_)) {  // undone or deleted meanwhile
    ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return;
  }
  ImGui::TextDisabled("frame '%s'", id_.c_str());
  ImGui::SetNextItemWidth(320);
  ImGui::InputTextWithHint("##frame title", "title", title_, sizeof title_);
  noteFrameWidget("frame title field");
  ImGui::InputTextMultiline("##frame comment", comment_, sizeof comment_, ImVec2(320, 90));
  noteFrameWidget("frame comment field");
  // Title and comment change together, one undo step; Enter in a field is left to ImGui
  // (a newline in the comment).
  if (ImGui::Button("apply")) {
    refusal_ = editor.setFrameText(id_, title_, comment_);
    if (refusal_.empty()) ImGui::CloseCurrentPopup();
  }
  noteFrameWidget("frame apply");
  ImGui::SameLine();
  if (ImGui::Button("hold the selection")) {
    refusal_ = editor.setFrameNodes(id_, selection);
    if (refusal_.empty()) ImGui::CloseCurrentPopup();
  }
  noteFrameWidget("frame hold selection");
  ImGui::SameLine();
  if (ImGui::Button("delete frame")) {
    refusal_ = editor.deleteFrame(id_);
    ImGui::CloseCurrentPopup();
  }
  noteFrameWidget("frame delete");
  if (!refusal_.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", refusal_.c_str());
  ImGui::EndPopup();
}

}  // namespace wg::editor
