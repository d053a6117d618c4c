#include "editor/editor_window.h"

#include <epoxy/gl.h>  // before GLFW and ImGui's OpenGL backend
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <new>
#include <iostream>
#include <memory>

#include "codegen/output_files.h"
#include "core/graph_edit.h"
#include "core/graph_imports.h"
#include "core/graph_io.h"
#include "core/graph_node_type.h"
#include "editor/clipboard_graph.h"
#include "editor/edit_script.h"
#include "editor/error_list.h"
#include "editor/file_watcher.h"
#include "editor/function_node_ports.h"
#include "editor/graph_change.h"
#include "editor/graph_layout.h"
#include "editor/inspector.h"
#include "editor/key_events.h"
#include "editor/layout_patch.h"
#include "editor/live_preview.h"
#include "editor/node_canvas.h"
#include "core/node_preview_graph.h"
#include "editor/orbit_camera.h"
#include "editor/panel_layout.h"
#include "editor/panel_splitters.h"
#include "editor/script_input.h"
#include "editor/script_runner.h"
#include "editor/unreached_nodes.h"
#include "editor/widget_rects.h"
#include "nodes/registry.h"
#include "runtime/glfw_context.h"
#include "runtime/image.h"
#include "runtime/runtime_error.h"


namespace wg::editor {

// ---------------------------------------------------------------------------------------
// UI

namespace {

// Panels stay under the splitters (editor/panel_splitters.h) when clicked.
constexpr ImGuiWindowFlags kPanel = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus;

void placeNext(float x, float y, float w, float h) {
  ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(w, h), ImGuiCond_Always);
}

}  // namespace

void EditorWindow::drawPreviewPanel(float x, float y, float w, float h) {
  placeNext(x, y, w, h);
  ImGui::Begin("Preview", nullptr, kPanel | ImGuiWindowFlags_NoScrollbar);
  ImVec2 avail = ImGui::GetContentRegionAvail();
  float controls = ImGui::GetFrameHeightWithSpacing() * 3 + ImGui::GetTextLineHeightWithSpacing();
  float aspect = static_cast<float>(options_.previewWidth) / static_cast<float>(options_.previewHeight);
  float iw = avail.x, ih = avail.x / aspect;
  if (ih > avail.y - controls) ih = std::max(avail.y - controls, 20.0f), iw = ih * aspect;
  ImVec2 at = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("view", ImVec2(iw, ih), ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  if (preview_.ready()) {
    // GL textures are bottom-up: flip v.
    dl->AddImage(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(preview_.texture())), at,
                 ImVec2(at.x + iw, at.y + ih), ImVec2(0, 1), ImVec2(1, 0));
  } else {
    dl->AddRectFilled(at, ImVec2(at.x + iw, at.y + ih), IM_COL32(20, 20, 20, 255));
    dl->AddText(ImVec2(at.x + 10, at.y + 10), IM_COL32(230, 120, 120, 255), "no preview: the graph has not compiled yet");
  }
  ImGuiIO& io = ImGui::GetIO();
  if (ImGui::IsItemActive() && ImGui::IsMouseDown(ImGuiMouseButton_Left) && (io.MouseDelta.x || io.MouseDelta.y))
    orbit_.orbit(io.MouseDelta.x, io.MouseDelta.y), previewDirty_ = true, cameraName_ = "(orbit)";
  if (ImGui::IsItemActive() && ImGui::IsMouseDown(ImGuiMouseButton_Right) && (io.MouseDelta.x || io.MouseDelta.y))
    orbit_.pan(io.MouseDelta.x, io.MouseDelta.y), previewDirty_ = true, cameraName_ = "(orbit)";
  if (ImGui::IsItemHovered() && io.MouseWheel != 0) orbit_.zoom(io.MouseWheel), previewDirty_ = true, cameraName_ = "(orbit)";

  ImGui::SetNextItemWidth(120);
  if (ImGui::BeginCombo("camera", cameraName_.c_str())) {
    for (const auto& name : rt::cameraPresetNames())
      if (ImGui::Selectable(name.c_str(), name == cameraName_)) {
        orbit_ = OrbitCamera::fromCamera(*rt::cameraPreset(name));
        cameraName_ = name;
        previewDirty_ = true;
      }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  if (ImGui::Button(playing_ ? "pause" : "play")) playing_ = !playing_;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(std::max(100.0f, iw - 330));
  // ImGui's slider edits a float; the scene keeps seconds in double (phases at large times).
  float shownTime = static_cast<float>(scene_.time);
  if (ImGui::SliderFloat("time", &shownTime, 0, std::max(60.0f, shownTime), "%.2f s")) {
    scene_.time = shownTime;
    previewDirty_ = true;
  }
  ImGui::SetNextItemWidth(160);
  if (ImGui::SliderFloat("sun azimuth", &scene_.sunAzimuthDegrees, 0, 360, "%.0f deg")) previewDirty_ = true;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(160);
  if (ImGui::SliderFloat("sun elevation", &scene_.sunElevationDegrees, -10, 90, "%.0f deg")) previewDirty_ = true;
  ImGui::SameLine();
  if (ImGui::Checkbox("buoys", &buoys_)) previewDirty_ = true;
  // The output transform (the graph's "view" until changed here; not saved to the graph).
  ViewTransform view = currentView();
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90);
  if (ImGui::BeginCombo("tone map", std::string(toneMapperName(view.toneMapper)).c_str())) {
    for (std::string_view name : toneMapperNames())
      if (ImGui::Selectable(std::string(name).c_str(), name == toneMapperName(view.toneMapper))) {
        view_.toneMapper = std::string(name);
        previewDirty_ = true;
      }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  ImGui::SetNextItemWidth(120);
  float ev = static_cast<float>(view.exposureEv);
  if (ImGui::SliderFloat("exposure", &ev, -8, 8, "%+.1f EV")) {
    view_.exposure = ev;
    previewDirty_ = true;
  }
  ImGui::Text("frame %.1f ms", frameMs_);
  ImGui::SameLine();
  if (lastLatency_) ImGui::Text("| edit to pixels: %s", lastLatency_->text().c_str());
  else ImGui::TextDisabled("| edit to pixels: (make an edit)");
  ImGui::End();
}

// Above the inspector while a subgraph is open: the files it was opened from, and the
// way back (asking first when the subgraph has unsaved changes).
void EditorWindow::drawSubgraphBar() {
  if (parents_.empty()) return;
  std::string trail;
  for (const auto& p : parents_) trail += std::filesystem::path(p.path).filename().string() + " > ";
  ImGui::TextDisabled("%s%s", trail.c_str(), std::filesystem::path(path_).filename().c_str());
  std::string label = "back to " + std::filesystem::path(parents_.back().path).filename().string();
  if (ImGui::Button(label.c_str())) {
    if (editor_.dirty()) ImGui::OpenPopup("unsaved subgraph");
    else backRequest_ = true;
  }
  if (ImGui::BeginPopupModal("unsaved subgraph", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("%s has unsaved changes.", std::filesystem::path(path_).filename().c_str());
    if (ImGui::Button("save, then go back")) {
      if (writeGraph(path_)) backRequest_ = true;
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("discard them")) {
      backRequest_ = true;
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("cancel")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  ImGui::Separator();
}

// "recent": the graphs opened last (remembered with the panel sizes); one with unsaved
// changes here asks before they are let go.
void EditorWindow::drawRecentFiles() {
  if (ImGui::Button("recent")) recentConfirm_.clear(), ImGui::OpenPopup("recent files");
  widgetRects().note("recent", {ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y, ImGui::GetItemRectMax().x, ImGui::GetItemRectMax().y});
  if (!ImGui::BeginPopup("recent files")) return;
  std::error_code ec;
  std::string current = std::filesystem::absolute(path_, ec).lexically_normal().string();
  int shown = 0;
  for (const std::string& file : settings_.recent) {
    if (file == current) continue;
    bool chosen = ImGui::Selectable(file.c_str(), file == recentConfirm_, ImGuiSelectableFlags_DontClosePopups);
    widgetRects().note("recent " + std::to_string(shown++),
                       {ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y, ImGui::GetItemRectMax().x, ImGui::GetItemRectMax().y});
    if (chosen && !editor_.dirty()) openRecentRequest_ = file, ImGui::CloseCurrentPopup();
    else if (chosen) recentConfirm_ = file;
  }
  if (shown == 0) ImGui::TextDisabled("no other graph opened yet");
  if (!recentConfirm_.empty()) {
    ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.4f, 1.0f), "%s has unsaved changes.", std::filesystem::path(path_).filename().c_str());
    if (ImGui::Button("discard them and open")) openRecentRequest_ = recentConfirm_, ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

void EditorWindow::drawInspectorPanel(float x, float y, float w, float h) {
  placeNext(x, y, w, h);
  ImGui::Begin("Inspector", nullptr, kPanel);
  drawSubgraphBar();
  if (ImGui::Button("save")) writeGraph(path_);
  ImGui::SameLine();
  if (ImGui::Button("save as")) {
    std::snprintf(saveAsPath_.data(), saveAsPath_.size(), "%s", path_.c_str());
    saveAsRefusal_.clear();
    ImGui::OpenPopup("save as");
  }
  if (ImGui::BeginPopup("save as")) {
    ImGui::SetNextItemWidth(360);
    bool enter = ImGui::InputText("##path", saveAsPath_.data(), saveAsPath_.size(), ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if (ImGui::Button("save") || enter) {
      saveAsRefusal_ = saveAs(saveAsPath_.data());
      if (saveAsRefusal_.empty()) ImGui::CloseCurrentPopup();
    }
    if (!saveAsRefusal_.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", saveAsRefusal_.c_str());
    ImGui::EndPopup();
  }
  ImGui::SameLine();
  drawRecentFiles();
  ImGui::SameLine();
  ImGui::BeginDisabled(!editor_.canUndo());
  if (ImGui::Button("undo")) editor_.undo();
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled) && editor_.canUndo())
    ImGui::SetTooltip("undo %s", editor_.undoLabel().c_str());
  ImGui::SameLine();
  ImGui::BeginDisabled(!editor_.canRedo());
  if (ImGui::Button("redo")) editor_.redo();
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled) && editor_.canRedo())
    ImGui::SetTooltip("redo %s", editor_.redoLabel().c_str());
  ImGui::SameLine();
  ImGui::TextDisabled("%s%s", std::filesystem::path(path_).filename().c_str(), editor_.dirty() ? " (modified)" : "");
  if (ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen)) drawParameterInspector(editor_);
  if (ImGui::CollapsingHeader("Selected node", ImGuiTreeNodeFlags_DefaultOpen)) {
    // The thumbnail first, so it stays in view above a long list of inputs and options.
    const Node* n = editor_.graph().findNode(selected_);
    std::vector<PortSpec> outputs;
    if (auto ports = n ? editorPortsOf(editor_.graph(), registry_, *n) : std::nullopt) outputs = std::move(ports->outputs);
    if (thumb_ && thumb_->ready())
      ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(thumb_->texture())), ImVec2(192, 108), ImVec2(0, 1),
                   ImVec2(1, 0));
    else if (!selected_.empty() && !thumbMessage_.empty())
      ImGui::TextDisabled("no thumbnail: %s", thumbMessage_.c_str());
    if (outputs.size() > 1) {
      ImGui::SetNextItemWidth(140);
      if (ImGui::BeginCombo("output", outputs[static_cast<size_t>(std::min<int>(thumbPort_, static_cast<int>(outputs.size()) - 1))].name.c_str())) {
        for (int i = 0; i < static_cast<int>(outputs.size()); ++i)
          if (ImGui::Selectable(outputs[static_cast<size_t>(i)].name.c_str(), i == thumbPort_))
            thumbPort_ = i, thumbStale_ = true;
        ImGui::EndCombo();
      }
    }
    if (drawNodeInspector(editor_, registry_, selected_, std::filesystem::path(path_).parent_path().string()))
      openRequest_ = selected_;
  }
  ImGui::End();
}

void EditorWindow::drawErrorPanel(float x, float y, float w, float h) {
  placeNext(x, y, w, h);
  ImGui::Begin("Errors", nullptr, kPanel | ImGuiWindowFlags_HorizontalScrollbar);
  if (!status_.empty()) ImGui::TextWrapped("%s", status_.c_str());
  if (errors_.empty()) {
    ImGui::TextColored(ImVec4(0.5f, 0.9f, 0.5f, 1), "no errors");
  } else {
    ImGui::TextColored(ImVec4(1, 0.6f, 0.4f, 1), "%s", errorContext_.c_str());
    // Paths relative to the opened graph's folder, where every subgraph lies.
    std::string folder = std::filesystem::path(options_.graphPath).parent_path().string();
    for (size_t i = 0; i < errors_.size(); ++i) {
      const Diagnostic& e = errors_[i];
      std::string node = nodeToSelect(e, editor_.graph());
      ImGui::PushID(static_cast<int>(i));
      if (ImGui::Selectable(errorListText(e, folder).c_str(), !node.empty() && node == selected_) && !node.empty())
        selected_ = node;
      ImGui::PopID();
    }
  }
  ImGui::End();
}

void EditorWindow::drawCanvasPanel(float x, float y, float w, float h) {
  placeNext(x, y, w, h);
  ImGui::Begin("Nodes", nullptr, kPanel | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
  ImGui::TextDisabled("drag: move, link, box-select | wheel, = -: zoom | Home, F: frame | middle, Alt+drag: pan | "
                      "right-click: add (on a link: insert) | Del, Ctrl+Del: reconnect | Ctrl+C/X/V/D");
  if (haveGraph_) canvas_.draw(editor_, registry_, selected_, errors_, keys_);
  if (std::string node = canvas_.takeOpenRequest(); !node.empty()) openRequest_ = node;
  ImGui::End();
}

// From the frame's key presses (editor/key_events.h), so a tap between two frames counts.
// Not while a text field has the keyboard: Ctrl+Z there is the field's own undo.
void EditorWindow::shortcuts() {
  if (ImGui::GetIO().WantTextInput) return;
  for (const KeyPress& k : keys_) {
    if (!(k.mods & GLFW_MOD_CONTROL)) continue;
    bool shift = k.mods & GLFW_MOD_SHIFT;
    if (k.key == GLFW_KEY_Z) shift ? editor_.redo() : editor_.undo();
    if (k.key == GLFW_KEY_Y) editor_.redo();
    if (k.key == GLFW_KEY_S) writeGraph(path_);
    if (k.key == GLFW_KEY_C || k.key == GLFW_KEY_X || k.key == GLFW_KEY_V || k.key == GLFW_KEY_D) clipboardCommand(k.key);
  }
}

// Copy, cut, paste, duplicate (editor/clipboard_graph.h). A paste that cannot go in is a
// message in the error panel (and on stderr); the graph and its undo history stay as they were.
void EditorWindow::clipboardCommand(int key) {
  std::vector<std::string> selection = canvas_.selection();
  std::vector<std::string> added;
  std::string why;
  if (key == GLFW_KEY_V) {
    const char* text = ImGui::GetClipboardText();
    why = pasteNodes(editor_, text ? text : "", canvas_.pasteAnchor(), &added);
    if (!why.empty()) why = "paste refused: " + why;
  } else if (selection.empty()) {
    why = "nothing selected to copy, cut or duplicate";
  } else if (key == GLFW_KEY_D) {
    const Node* first = editor_.graph().findNode(selection.front());
    std::array<double, 2> at = first && first->editorPosition ? *first->editorPosition : std::array<double, 2>{0, 0};
    for (const auto& id : selection)
      if (const Node* n = editor_.graph().findNode(id); n && n->editorPosition)
        at = {std::min(at[0], (*n->editorPosition)[0]), std::min(at[1], (*n->editorPosition)[1])};
    why = pasteNodes(editor_, copyNodesAsJson(editor_.graph(), selection), {at[0] + 40, at[1] + 40}, &added);
  } else {
    ImGui::SetClipboardText(copyNodesAsJson(editor_.graph(), selection).c_str());
    if (key == GLFW_KEY_X) why = editor_.deleteNodes(selection);
    status_ = std::to_string(selection.size()) + (selection.size() == 1 ? " node " : " nodes ") + (key == GLFW_KEY_X ? "cut" : "copied");
  }
  if (!why.empty()) {
    status_ = why;
    std::cerr << "watergraph-editor: " << why << "\n";
    return;
  }
  if (!added.empty()) {
    canvas_.select(added);
    selected_ = added.back();
    status_ = "pasted " + std::to_string(added.size()) + (added.size() == 1 ? " node" : " nodes");
  }
}

void EditorWindow::drawUi() {
  int fw = 0, fh = 0;
  window_.framebufferSize(&fw, &fh);
  float w = static_cast<float>(fw), h = static_cast<float>(fh);
  widgetRects().clear();  // noted again as they are drawn
  float left = std::floor(w * settings_.panels.leftWidth), top = std::floor(h * settings_.panels.previewHeight);
  float inspector = std::floor(h * settings_.panels.inspectorHeight);
  drawPreviewPanel(0, 0, left, top);
  drawCanvasPanel(0, top, left, h - top);
  drawInspectorPanel(left, 0, w - left, inspector);
  drawErrorPanel(left, inspector, w - left, h - inspector);
  if (drawPanelSplitters(settings_.panels, w, h)) rememberSettings();
  shortcuts();
}

void EditorWindow::writeScreenshot(const std::string& path) {
  int fw = 0, fh = 0;
  window_.framebufferSize(&fw, &fh);
  rt::Image img;
  img.width = fw, img.height = fh;
  img.rgba8.resize(static_cast<size_t>(fw) * static_cast<size_t>(fh) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, fw, fh, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba8.data());
  size_t row = static_cast<size_t>(fw) * 4;
  for (int y = 0; y < fh / 2; ++y)  // GL rows are bottom-up
    std::swap_ranges(img.rgba8.begin() + static_cast<ptrdiff_t>(static_cast<size_t>(y) * row),
                     img.rgba8.begin() + static_cast<ptrdiff_t>(static_cast<size_t>(y + 1) * row),
                     img.rgba8.begin() + static_cast<ptrdiff_t>(static_cast<size_t>(fh - 1 - y) * row));
  for (size_t i = 3; i < img.rgba8.size(); i += 4) img.rgba8[i] = 255;  // the window has no meaningful alpha
  rt::writePng(path, img);
}


}  // namespace wg::editor
