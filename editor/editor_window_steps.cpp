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
// What script steps do here (editor/script_runner.h runs them)

std::string EditorWindow::screenshot(const std::string& path) {
  pendingScreenshot_ = path;
  return "";
}

std::string EditorWindow::savePreview(const std::string& path) {
  if (!preview_.ready()) return "there is no preview (the graph never compiled)";
  rt::writePng(path, preview_.read());
  return "";
}

std::string EditorWindow::saveThumbnail(const std::string& path) {
  if (!thumb_ || !thumb_->ready()) return "no thumbnail: " + (thumbMessage_.empty() ? "no node selected" : thumbMessage_);
  rt::writePng(path, thumb_->read());
  return "";
}

std::string EditorWindow::select(const std::string& node, int port) {
  selected_ = thumbNode_ = node;
  thumbPort_ = port;
  thumbStale_ = true;
  if (!selected_.empty() && !editor_.graph().findNode(selected_)) return "no node '" + selected_ + "'";
  return "";
}

std::string EditorWindow::camera(const std::string& preset) {
  auto c = rt::cameraPreset(preset);
  if (!c) return "no camera preset '" + preset + "'";
  orbit_ = OrbitCamera::fromCamera(*c);
  cameraName_ = preset;
  previewDirty_ = true;
  return "";
}

void EditorWindow::setTime(float seconds) {
  scene_.time = seconds;
  previewDirty_ = true;
}

// ---------------------------------------------------------------------------------------
// Subgraphs: one file is edited at a time; opening an instance's subgraph keeps the graph
// it was opened from (unsaved edits, undo history, canvas) to come back to.

std::string EditorWindow::openSubgraph(const std::string& node) {
  if (!haveGraph_) return "the graph has not loaded";
  const Node* n = editor_.graph().findNode(node);
  if (!n) return "no node '" + node + "'";
  GraphNodeType type = nodeTypeOf(editor_.graph(), registry_, n->type);
  if (!type.isInstance()) return "node '" + node + "' (" + n->type + ") is not a subgraph instance";
  if (!type.import->graph) return "the subgraph '" + type.import->path + "' of node '" + node + "' did not load (see the errors)";
  std::string file = type.import->graph->file;
  std::string written = type.import->path;  // the import as the parent writes it: short, and what the user knows
  parents_.push_back({path_, std::move(editor_), std::move(diskText_), std::move(diskGraph_), diskRevision_, node, std::move(canvas_)});
  path_ = file;
  forgetGraph();
  if (!loadFromDisk(true)) {
    std::string why = errors_.empty() ? "cannot read " + file : formatText(errors_.front());
    OpenParent p = std::move(parents_.back());
    parents_.pop_back();
    path_ = p.path, editor_ = std::move(p.editor), diskText_ = std::move(p.diskText), diskGraph_ = std::move(p.diskGraph);
    diskRevision_ = p.diskRevision, canvas_ = std::move(p.canvas), selected_ = p.instance, haveGraph_ = true;
    watcher_.watch(filesToWatch(editor_.graph()));
    recompile();
    return "cannot open the subgraph: " + why;
  }
  recompile();
  showFileName();
  status_ = "editing " + written + ", the subgraph of node '" + node + "'; save it, then go back";
  return "";
}

std::string EditorWindow::back(bool discard) {
  if (parents_.empty()) return "no graph to go back to: this is the one the editor opened";
  if (editor_.dirty() && !discard)
    return path_ + " has unsaved changes: save them first (or go back with \"discard\": true)";
  OpenParent p = std::move(parents_.back());
  parents_.pop_back();
  path_ = p.path, editor_ = std::move(p.editor), diskText_ = std::move(p.diskText), diskGraph_ = std::move(p.diskGraph);
  diskRevision_ = p.diskRevision, canvas_ = std::move(p.canvas), selected_ = p.instance, haveGraph_ = true;
  watcher_.watch(filesToWatch(editor_.graph()));
  // The subgraph may have been saved, and this file changed on disk meanwhile: both read again.
  loadFromDisk(false);
  recompile();
  pending_.active = false;  // coming back is not an edit to time
  showFileName();
  status_ = "back to " + std::filesystem::path(path_).filename().string() + ", compiled with its subgraphs as saved";
  return "";
}

void EditorWindow::showFileName() {
  std::string title = "watergraph-editor - " + std::filesystem::path(path_).filename().string();
  glfwSetWindowTitle(window_.window(), title.c_str());
}

// Between frames, so that no panel draws half of one file and half of another.
void EditorWindow::navigate() {
  std::string why;
  if (backRequest_) why = back(true);  // unsaved changes were saved or let go in the dialog
  else if (!openRequest_.empty()) why = openSubgraph(openRequest_);
  if (!why.empty()) status_ = why;
  backRequest_ = false;
  openRequest_.clear();
}


// Save as: the graph written to `path`, which the editor then edits (watched, saved by Ctrl+S,
// named in the title); the file it was opened from stays as it was on disk. Imports are
// relative to the graph's folder, so a graph that imports stays in its folder.
std::string EditorWindow::saveAs(const std::string& path) {
  if (!haveGraph_) return "nothing to save: the file has not loaded yet";
  if (path.empty()) return "save as: no file name";
  if (!parents_.empty()) return "save as: go back to the graph the editor opened first (a subgraph keeps its file)";
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path from = fs::absolute(path_, ec).parent_path(), to = fs::absolute(path, ec).parent_path();
  if (!editor_.graph().imports.empty() && from.lexically_normal() != to.lexically_normal())
    return "save as: this graph imports subgraphs by paths relative to its folder; save it in the same folder";
  if (!writeGraph(path)) return status_;
  std::string text = saveGraph(editor_.graph());
  Diagnostics ignore;
  path_ = path;
  options_.graphPath = path;
  auto g = parseGraph(text, path, ignore);
  if (g) diskGraph_ = *g, loadImports(*g, ignore);
  diskText_ = text;
  editor_.markSaved();
  diskRevision_ = editor_.revision();
  watcher_ = FileWatcher(path);
  if (g) watcher_.watch(filesToWatch(*g));  // the new file and what it imports
  recompile();  // diagnostics name the new file
  showFileName();
  rememberOpened(path);
  status_ = "saved as " + path + "; editing it now";
  return "";
}

std::string EditorWindow::open(const std::string& path, bool discard) {
  if (!parents_.empty()) return "open: go back to the graph the editor opened first";
  if (editor_.dirty() && !discard) return path_ + " has unsaved changes: save them first (or open with \"discard\": true)";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return "open: " + path + ": no such file";
  path_ = path;
  options_.graphPath = path;
  forgetGraph();
  watcher_ = FileWatcher(path);
  loadFromDisk(true);  // one that does not load lists why, and reloads once fixed on disk
  recompile();
  pending_.active = false;
  showFileName();
  rememberOpened(path);
  if (haveGraph_) status_ = "opened " + path;
  return "";
}

void EditorWindow::rememberSettings() {
  if (settingsPath_.empty()) return;
  if (std::string why = saveEditorSettings(settingsPath_, settings_); !why.empty()) status_ = "settings not remembered: " + why;
}

}  // namespace wg::editor
