#include "editor/editor_app.h"

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
namespace {

using Clock = std::chrono::steady_clock;

double msBetween(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); }

// An edit on its way to the screen: started when the edit was made, finished when the
// first frame showing it has been drawn and presented (after glFinish).
struct PendingLatency {
  bool active = false;
  bool rendered = false;  // the preview has been rendered with the change
  Clock::time_point start;
  std::string kind;       // "uniform", "recompile"
  double compileMs = 0, glMs = 0;
};

struct Latency {
  double totalMs = 0, compileMs = 0, glMs = 0;
  std::string kind;
  std::string text() const {
    char buf[160];
    if (kind == "recompile")
      std::snprintf(buf, sizeof buf, "%.1f ms (recompile: compile %.1f ms, GL %.1f ms)", totalMs, compileMs, glMs);
    else
      std::snprintf(buf, sizeof buf, "%.1f ms (%s, no recompile)", totalMs, kind.c_str());
    return buf;
  }
};

class App : private ScriptHost {
 public:
  App(const EditorOptions& options, rt::GlfwContext& window)
      : options_(options), window_(window), registry_(defaultRegistry()), path_(options.graphPath), editor_(Graph{}, &registry_),
        watcher_(options.graphPath), preview_(previewSettings(options.previewWidth, options.previewHeight, 128)) {
    auto preset = rt::cameraPreset(options.camera);  // checked by main
    orbit_ = OrbitCamera::fromCamera(preset ? *preset : rt::Camera{});
    cameraName_ = options.camera;
    if (options.time) scene_.time = *options.time, playing_ = false;
    view_ = options.view;
    bool batch = !options.script.empty() || options.frames > 0;
    if (batch) playing_ = false;  // deterministic runs
    // A batch run neither reads nor writes the user's settings unless it names a file.
    settingsPath_ = !options.settings.empty() ? options.settings : batch ? "" : defaultSettingsPath();
    if (!settingsPath_.empty())
      if (auto remembered = loadPanelLayout(settingsPath_)) panels_ = *remembered;
  }

  int run();

 private:
  static rt::RenderSettings previewSettings(int w, int h, int grid) {
    rt::RenderSettings s;
    s.width = w, s.height = h;
    s.waterGridQuads = grid;
    return s;
  }

  // --- model and files ---
  bool loadFromDisk(bool initial);
  bool reloadImports();
  void recompile();
  bool writeGraph(const std::string& path);  // the editor's graph to `path`; false when it could not
  void setErrors(const Diagnostics& d, const std::string& context);
  std::optional<Graph> graphToCompile(Diagnostics& d) const;
  void noteEdit() {
    pending_ = {};
    pending_.active = true;
    pending_.start = Clock::now();
  }
  // --- preview ---
  void processChange();
  void rebuildThumbnail();
  void renderPreviews();
  void finishLatency();
  // --- script steps (ScriptHost) ---
  bool graphLoaded() const override { return haveGraph_; }
  GraphEditor& graphEditor() override { return editor_; }
  void edited() override { noteEdit(); }
  const std::string& graphPath() const override { return path_; }
  int diskEvents() const override { return diskEvents_; }
  std::string save(const std::string& path) override { return writeGraph(path) ? "" : "cannot save " + path; }
  std::string screenshot(const std::string& path) override;
  std::string savePreview(const std::string& path) override;
  std::string saveThumbnail(const std::string& path) override;
  std::string select(const std::string& node, int port) override;
  std::string camera(const std::string& preset) override;
  void setTime(float seconds) override;
  // --- subgraphs: the file being edited, and the ones it was opened from ---
  std::string openSubgraph(const std::string& node) override;
  std::string back(bool discard) override;
  std::string input(const ScriptStep& step) override { return input_ ? input_->apply(step.args) : "no window"; }
  bool inputPending() const override { return input_ && input_->busy(); }
  void showFileName();
  void navigate();  // what the UI asked for in the last frame
  // --- UI ---
  void drawUi();
  void drawPreviewPanel(float x, float y, float w, float h);
  void drawInspectorPanel(float x, float y, float w, float h);
  void drawErrorPanel(float x, float y, float w, float h);
  void drawCanvasPanel(float x, float y, float w, float h);
  void drawSubgraphBar();
  void shortcuts();
  void clipboardCommand(int key);  // GLFW_KEY_C, X, V or D with Ctrl
  void writeScreenshot(const std::string& path);

  EditorOptions options_;
  rt::GlfwContext& window_;
  const Registry& registry_;
  std::string path_;         // the file being edited: the graph opened, or a subgraph opened from it
  GraphEditor editor_;
  bool haveGraph_ = false;   // a graph has loaded (saving is allowed)
  std::string diskText_;     // the file as last loaded or saved
  Graph diskGraph_;          // parsed from diskText_ (positions in the real file)
  long diskRevision_ = -1;   // editor revision equal to diskText_
  FileWatcher watcher_;
  int diskEvents_ = 0;       // changes on disk noticed (loaded or not)

  LivePreview preview_;
  std::optional<Graph> goodGraph_;  // what the preview runs
  long attemptedRevision_ = -1;
  std::vector<Diagnostic> errors_;
  std::vector<Diagnostic> goodWarnings_;  // the warnings of the graph the preview runs
  std::string errorContext_;
  std::string status_;

  std::string selected_;
  std::string thumbNode_;
  int thumbPort_ = 0;
  bool thumbStale_ = true;  // selection, output port or compiled graph changed
  std::unique_ptr<LivePreview> thumb_, retiredThumb_;
  std::string thumbMessage_;

  OrbitCamera orbit_;
  std::string cameraName_;
  rt::SceneOptions scene_;
  // --tonemap / --exposure, then what the view controls set, over the graph's "view".
  cli::ViewFlags view_;
  ViewTransform currentView() const {
    return view_.over(preview_.compiled() ? preview_.compiled()->program.view : ViewTransform{});
  }
  bool playing_ = true;
  bool previewDirty_ = true;
  double frameMs_ = 0;
  PendingLatency pending_;
  std::optional<Latency> lastLatency_;

  NodeCanvas canvas_;
  PanelLayout panels_;        // the splitters' positions
  std::string settingsPath_;  // where they are remembered ("" : not remembered)
  std::optional<ScriptRunner> script_;
  std::unique_ptr<ScriptedInput> input_;  // the script's keys and pointer
  std::vector<KeyPress> keys_;            // this frame's key presses (editor/key_events.h)
  std::string pendingScreenshot_;
  bool scriptFailed_ = false;

  // A graph left open below a subgraph, as it was, to come back to (its unsaved edits and
  // undo history included).
  struct OpenParent {
    std::string path;
    GraphEditor editor;
    std::string diskText;
    Graph diskGraph;
    long diskRevision = -1;
    std::string instance;  // the node whose subgraph was opened: selected again on the way back
    NodeCanvas canvas;
  };
  std::vector<OpenParent> parents_;
  std::string openRequest_;   // an instance to open, asked for by the UI
  bool backRequest_ = false;  // back to the parent, asked for by the UI (saved or discarded first)
};

// ---------------------------------------------------------------------------------------
// Model and files

bool App::loadFromDisk(bool initial) {
  Diagnostics d;
  auto text = readGraphFile(path_, d);
  if (text && haveGraph_ && *text == diskText_) return reloadImports();  // an imported file changed, or ours was touched
  std::optional<Graph> g;
  if (text) g = parseGraph(*text, path_, d);
  if (!g) {
    setErrors(d, haveGraph_ ? "the file on disk does not load; the editor keeps the last good graph"
                            : "the file does not load; fix it in any editor and it reloads here");
    return false;
  }
  Graph loaded = *g;
  // Imports that do not load leave their instances without ports; compiling lists why.
  Diagnostics importErrors;
  loadImports(loaded, importErrors);
  layoutUnplacedNodes(loaded);
  if (initial || !haveGraph_) editor_ = GraphEditor(loaded, &registry_);
  else editor_.replace(loaded, "reload from disk");
  editor_.markSaved();
  diskText_ = *text;
  diskGraph_ = loaded;
  diskRevision_ = editor_.revision();
  haveGraph_ = true;
  watcher_.watch(filesToWatch(editor_.graph()));
  if (!initial) {
    status_ = "reloaded from disk (undo brings back what was there before)";
    noteEdit();  // a change on disk counts from when it was noticed
  }
  return true;
}

// The graph file is as loaded but what it imports may not be: the instances' ports and
// the preview follow the imported files as they are now (those that no longer load keep
// their last good version for the ports; compiling lists their errors).
bool App::reloadImports() {
  if (editor_.graph().imports.empty()) return false;
  Graph now = editor_.graph();
  Diagnostics reportedByCompiling;
  loadImports(now, reportedByCompiling);
  editor_.adoptImports(now);
  watcher_.watch(filesToWatch(editor_.graph()));
  recompile();
  status_ = "imported graphs read again from disk";
  noteEdit();
  return true;
}

// Compiles the graph again at the next frame, whatever its revision: what it imports changed,
// or another file was shown in the preview.
void App::recompile() {
  goodGraph_.reset();
  attemptedRevision_ = -1;
  thumbStale_ = true;
}

bool App::writeGraph(const std::string& path) {
  if (!haveGraph_) {
    status_ = "nothing to save: the file has not loaded yet";
    std::cerr << "watergraph-editor: " << status_ << "\n";
    return false;
  }
  std::string text = saveGraph(editor_.graph());
  // Nodes moved, nothing else: the file keeps its own formatting (editor/layout_patch.h).
  if (path == path_ && diskRevision_ >= 0)
    if (auto patched = patchLayoutOnly(diskText_, diskGraph_, editor_.graph())) text = std::move(*patched);
  Diagnostics d;
  // Saving the open graph rewrites it in place: a link the user opened stays a link, as fmt
  // keeps it (codegen/output_files.h); a new path (save as) is written as it is named.
  if (!writeFileAtomically(path == path_ ? realPathForRewrite(path) : path, text, d)) {
    status_ = d.all().empty() ? "cannot save " + path : formatText(d.all().front());
    std::cerr << status_ << "\n";
    return false;
  }
  if (path == path_) {
    Diagnostics ignore;
    if (auto g = parseGraph(text, path, ignore)) diskGraph_ = *g;
    diskText_ = text;
    watcher_.acknowledge(path);
    editor_.markSaved();
    diskRevision_ = editor_.revision();
  }
  status_ = "saved " + path;
  return true;
}

void App::setErrors(const Diagnostics& d, const std::string& context) {
  errors_ = d.sorted();
  errorContext_ = context;
  for (const auto& e : errors_) std::cerr << formatText(e) << "\n";
}

// The graph as loaded keeps the positions of the real file; an edited graph is compiled
// from the text Save would write, so its errors point at lines of that text. Imports are
// loaded again each time, as `watergraph compile` would: the subgraph files as they are
// now, their errors in their own files.
std::optional<Graph> App::graphToCompile(Diagnostics& d) const {
  std::optional<Graph> g;
  if (editor_.revision() == diskRevision_) g = diskGraph_;
  else g = parseGraph(saveGraph(editor_.graph()), path_, d);
  if (!g || !loadImports(*g, d)) return std::nullopt;
  // Half-wired: what no output reaches is left out; its missing inputs are warnings.
  for (Diagnostic& w : pruneUnreachedNodes(*g, registry_)) d.add(std::move(w));
  // A function graph needs no output slots; without any it shows its first interface output.
  std::string why;
  if (auto shown = interfaceOutputGraph(*g, &why)) return shown;
  return g;
}

// ---------------------------------------------------------------------------------------
// Preview

void App::processChange() {
  if (!haveGraph_ || editor_.revision() == attemptedRevision_) return;
  attemptedRevision_ = editor_.revision();
  if (preview_.ready() && goodGraph_) {
    GraphChange change = compareGraphs(*goodGraph_, editor_.graph());
    if (!change.structural) {
      bool uniformsOnly = true;
      for (const auto& name : change.parameters)
        uniformsOnly &= preview_.setParameter(name, editor_.graph().findParameter(name)->defaultValue);
      if (uniformsOnly) {
        for (const auto& name : change.parameters)
          if (thumb_) thumb_->setParameter(name, editor_.graph().findParameter(name)->defaultValue);
        goodGraph_ = editor_.graph();
        errors_ = goodWarnings_;  // the same nodes as compiled: the same warnings
        if (change.parameters.empty()) pending_.active = false;  // a moved node: no pixels change
        pending_.kind = "uniform";
        previewDirty_ = true;
        return;
      }
    }
  }
  Diagnostics d;
  RebuildTimings t;
  auto g = graphToCompile(d);
  if (g && preview_.rebuild(*g, registry_, d, &t)) {
    goodGraph_ = editor_.graph();
    errors_ = goodWarnings_ = d.sorted();  // warnings, if any (half-wired nodes among them)
    for (const auto& w : errors_) std::cerr << formatText(w) << "\n";
    pending_.kind = "recompile";
    pending_.compileMs = t.compileMs;
    pending_.glMs = t.rendererMs;
    previewDirty_ = true;
    thumbStale_ = true;  // rebuild the thumbnail against the new graph
  } else {
    setErrors(d, preview_.ready() ? "the graph does not compile; the preview shows the last good version"
                                  : "the graph does not compile; no preview yet");
    pending_.active = false;
  }
}

void App::rebuildThumbnail() {
  if (selected_ != thumbNode_) thumbPort_ = 0, thumbNode_ = selected_, thumbStale_ = true;
  if (selected_.empty()) {
    if (thumb_) retiredThumb_ = std::move(thumb_);
    return;
  }
  // The main preview first: while an edit is on its way to the screen, the thumbnail
  // (a second compile) waits a frame, so it does not count in the edit-to-pixels time.
  if (!thumbStale_ || pending_.active) return;
  thumbStale_ = false;
  retiredThumb_ = std::move(thumb_);  // this frame's draw data may still show it
  thumbMessage_.clear();
  const Node* n = editor_.graph().findNode(selected_);
  std::optional<NodePorts> ports = n ? portsOfGraphNode(editor_.graph(), registry_, *n) : std::nullopt;
  if (!ports || ports->outputs.empty()) {
    thumbMessage_ = "no output to preview";
    return;
  }
  thumbPort_ = std::clamp(thumbPort_, 0, static_cast<int>(ports->outputs.size()) - 1);
  std::string why;
  // What neither the outputs nor this node reach is left out, as for the preview.
  Graph wired = editor_.graph();
  pruneUnreachedNodes(wired, registry_, {selected_});
  auto g = nodeOutputGraph(wired, registry_, selected_, ports->outputs[static_cast<size_t>(thumbPort_)].name, &why);
  if (!g) {
    thumbMessage_ = why;
    return;
  }
  auto t = std::make_unique<LivePreview>(previewSettings(192, 108, 64));
  Diagnostics d;
  if (!t->rebuild(*g, registry_, d)) {
    thumbMessage_ = d.all().empty() ? "does not compile" : d.sorted().front().message;
    return;
  }
  thumb_ = std::move(t);
  previewDirty_ = true;
}

void App::renderPreviews() {
  if (!previewDirty_ && !playing_) return;
  rt::Camera cam = orbit_.toCamera();
  std::string error;
  if (preview_.ready()) frameMs_ = preview_.render(cam, scene_, currentView(), &error);
  if (!error.empty()) {
    Diagnostics d;
    d.error(DiagCode::RuntimeRejected, SourceRef{path_, 0, 0}, error);
    setErrors(d, "the preview failed to render; edit the graph to try again");
    goodGraph_.reset();
  }
  if (thumb_) thumb_->render(cam, scene_, currentView());
  previewDirty_ = false;
  if (pending_.active) pending_.rendered = true;
}

void App::finishLatency() {
  // An edit that changed nothing to draw (the graph came back to the compiled state).
  if (pending_.active && !pending_.rendered && msBetween(pending_.start, Clock::now()) > 2000) pending_.active = false;
  if (!pending_.active || !pending_.rendered) return;
  glFinish();  // the frame is on screen (or at least done), not only queued
  Latency l;
  l.totalMs = msBetween(pending_.start, Clock::now());
  l.kind = pending_.kind;
  l.compileMs = pending_.compileMs;
  l.glMs = pending_.glMs;
  lastLatency_ = l;
  pending_.active = false;
  if (options_.stats) std::cout << "edit-to-pixels: " << l.text() << std::endl;
}

// ---------------------------------------------------------------------------------------
// What script steps do here (editor/script_runner.h runs them)

std::string App::screenshot(const std::string& path) {
  pendingScreenshot_ = path;
  return "";
}

std::string App::savePreview(const std::string& path) {
  if (!preview_.ready()) return "there is no preview (the graph never compiled)";
  rt::writePng(path, preview_.read());
  return "";
}

std::string App::saveThumbnail(const std::string& path) {
  if (!thumb_ || !thumb_->ready()) return "no thumbnail: " + (thumbMessage_.empty() ? "no node selected" : thumbMessage_);
  rt::writePng(path, thumb_->read());
  return "";
}

std::string App::select(const std::string& node, int port) {
  selected_ = thumbNode_ = node;
  thumbPort_ = port;
  thumbStale_ = true;
  if (!selected_.empty() && !editor_.graph().findNode(selected_)) return "no node '" + selected_ + "'";
  return "";
}

std::string App::camera(const std::string& preset) {
  auto c = rt::cameraPreset(preset);
  if (!c) return "no camera preset '" + preset + "'";
  orbit_ = OrbitCamera::fromCamera(*c);
  cameraName_ = preset;
  previewDirty_ = true;
  return "";
}

void App::setTime(float seconds) {
  scene_.time = seconds;
  previewDirty_ = true;
}

// ---------------------------------------------------------------------------------------
// Subgraphs: one file is edited at a time; opening an instance's subgraph keeps the graph
// it was opened from (unsaved edits, undo history, canvas) to come back to.

std::string App::openSubgraph(const std::string& node) {
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
  editor_ = GraphEditor(Graph{}, &registry_);
  haveGraph_ = false;
  diskText_.clear();
  diskRevision_ = -1;
  canvas_ = NodeCanvas{};
  selected_.clear();
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

std::string App::back(bool discard) {
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

void App::showFileName() {
  std::string title = "watergraph-editor - " + std::filesystem::path(path_).filename().string();
  glfwSetWindowTitle(window_.window(), title.c_str());
}

// Between frames, so that no panel draws half of one file and half of another.
void App::navigate() {
  std::string why;
  if (backRequest_) why = back(true);  // unsaved changes were saved or let go in the dialog
  else if (!openRequest_.empty()) why = openSubgraph(openRequest_);
  if (!why.empty()) status_ = why;
  backRequest_ = false;
  openRequest_.clear();
}

// ---------------------------------------------------------------------------------------
// UI

// Panels stay under the splitters (editor/panel_splitters.h) when clicked.
constexpr ImGuiWindowFlags kPanel = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus;

void placeNext(float x, float y, float w, float h) {
  ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(w, h), ImGuiCond_Always);
}

void App::drawPreviewPanel(float x, float y, float w, float h) {
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
void App::drawSubgraphBar() {
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

void App::drawInspectorPanel(float x, float y, float w, float h) {
  placeNext(x, y, w, h);
  ImGui::Begin("Inspector", nullptr, kPanel);
  drawSubgraphBar();
  if (ImGui::Button("save")) writeGraph(path_);
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
    if (auto ports = n ? portsOfGraphNode(editor_.graph(), registry_, *n) : std::nullopt) outputs = std::move(ports->outputs);
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
    if (drawNodeInspector(editor_, registry_, selected_)) openRequest_ = selected_;
  }
  ImGui::End();
}

void App::drawErrorPanel(float x, float y, float w, float h) {
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

void App::drawCanvasPanel(float x, float y, float w, float h) {
  placeNext(x, y, w, h);
  ImGui::Begin("Nodes", nullptr, kPanel | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
  ImGui::TextDisabled("drag: move, link from an output, box-select | wheel, = -: zoom | Home / F: frame all / selection | "
                      "middle or Alt+drag: pan | right-click: add, disconnect | Del");
  if (haveGraph_) canvas_.draw(editor_, registry_, selected_, errors_, keys_);
  if (std::string node = canvas_.takeOpenRequest(); !node.empty()) openRequest_ = node;
  ImGui::End();
}

// From the frame's key presses (editor/key_events.h), so a tap between two frames counts.
// Not while a text field has the keyboard: Ctrl+Z there is the field's own undo.
void App::shortcuts() {
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
void App::clipboardCommand(int key) {
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

void App::drawUi() {
  int fw = 0, fh = 0;
  window_.framebufferSize(&fw, &fh);
  float w = static_cast<float>(fw), h = static_cast<float>(fh);
  widgetRects().clear();  // noted again as they are drawn
  float left = std::floor(w * panels_.leftWidth), top = std::floor(h * panels_.previewHeight);
  float inspector = std::floor(h * panels_.inspectorHeight);
  drawPreviewPanel(0, 0, left, top);
  drawCanvasPanel(0, top, left, h - top);
  drawInspectorPanel(left, 0, w - left, inspector);
  drawErrorPanel(left, inspector, w - left, h - inspector);
  if (drawPanelSplitters(panels_, w, h) && !settingsPath_.empty()) {
    if (std::string why = savePanelLayout(settingsPath_, panels_); !why.empty()) status_ = "panel sizes not remembered: " + why;
  }
  shortcuts();
}

void App::writeScreenshot(const std::string& path) {
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

int App::run() {
  if (!options_.script.empty()) {
    std::string error;
    auto steps = loadScript(options_.script, &error);
    if (!steps) {
      std::cerr << error << "\n";
      return 1;
    }
    script_.emplace(std::move(*steps), options_.script);
  }
  loadFromDisk(true);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // the layout is fixed; write no imgui.ini
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window_.window(), true);
  ImGui_ImplOpenGL3_Init("#version 450 core");
  installKeyQueue(window_.window());
  if (script_) input_ = std::make_unique<ScriptedInput>(window_.window());

  processChange();  // the first compile, before the first frame
  renderPreviews();
  bool batch = !options_.script.empty() || options_.frames > 0;
  int framesAfterScript = options_.frames > 0 ? options_.frames : 2;
  auto lastTick = Clock::now();
  while (!window_.shouldClose()) {
    glfwPollEvents();
    auto now = Clock::now();
    float dt = static_cast<float>(msBetween(lastTick, now) / 1000.0);
    lastTick = now;
    if (playing_) scene_.time += dt;

    if (watcher_.changed()) {
      ++diskEvents_;
      loadFromDisk(false);
    }
    navigate();
    // A step sees every earlier step on screen; its own edit is shown in this frame.
    if (script_ && !scriptFailed_ && !script_->step(*this)) {
      std::cerr << script_->error() << "\n";
      scriptFailed_ = true;
    }

    keys_ = takeKeyPresses();  // after the script's, which come as GLFW's do

    long before = editor_.revision();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    if (input_) input_->overridePointer();
    ImGui::NewFrame();
    drawUi();
    ImGui::Render();
    if (editor_.revision() != before) noteEdit();  // measured from here to its first frame

    // The UI refers to the preview by its texture, which is sampled only when the draw
    // data is drawn below: an edit made in this frame's UI is on screen in this frame.
    processChange();
    rebuildThumbnail();
    renderPreviews();

    int fw = 0, fh = 0;
    window_.framebufferSize(&fw, &fh);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fw, fh);
    glClearColor(0.1f, 0.1f, 0.12f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    // No preview program stays current: ImGui's backend restores the program it found, and
    // one deleted meanwhile (a thumbnail let go after this frame) would then be a GL error
    // (glUseProgram of a deleted name) that the next preview frame reports as WG043.
    glUseProgram(0);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    bool scriptDone = scriptFailed_ || !script_ || script_->done();
    bool lastFrame = batch && scriptDone && --framesAfterScript <= 0;
    if (!pendingScreenshot_.empty()) writeScreenshot(pendingScreenshot_), pendingScreenshot_.clear();
    if (lastFrame && !options_.screenshot.empty()) writeScreenshot(options_.screenshot);
    window_.swapBuffers();
    preview_.endFrame();
    retiredThumb_.reset();
    finishLatency();
    if (lastFrame) break;
  }

  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  if (scriptFailed_) return 1;
  bool hasErrors = std::any_of(errors_.begin(), errors_.end(), [](const Diagnostic& d) { return d.severity == Severity::Error; });
  return hasErrors || !haveGraph_ ? 1 : 0;
}

}  // namespace

int runEditor(const EditorOptions& options) {
  try {
    rt::WindowOptions w;
    w.width = options.windowWidth;
    w.height = options.windowHeight;
    w.title = "watergraph-editor - " + std::filesystem::path(options.graphPath).filename().string();
    w.vsync = options.script.empty() && options.frames == 0;  // batch runs do not wait for the display
    auto window = rt::GlfwContext::create(w);
    int status = 0;
    {
      App app(options, *window);
      status = app.run();
    }  // GL objects go before the window
    return status;
  } catch (const rt::RuntimeError& e) {
    std::cerr << "watergraph-editor: " << e.what() << "\n";
    return e.exitCode();
  } catch (const std::bad_alloc&) {
    std::cerr << "watergraph-editor: out of memory: the editor needs more memory than this process can get "
                 "(ulimit -v, a container's limit, or a smaller --size, --preview-size or graph)\n";
    return 2;
  }
}

}  // namespace wg::editor
