#pragma once
// The editor's window (editor/editor_app.h runs it): the state behind the panels and what
// each part does, split by job over editor_app.cpp (files, compiling, the preview, the frame
// loop), editor_window_steps.cpp (script steps and subgraph navigation) and
// editor_panels.cpp (the ImGui panels and shortcuts).
#include <array>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/graph_edit.h"
#include "editor/editor_app.h"
#include "editor/file_watcher.h"
#include "editor/key_events.h"
#include "editor/live_preview.h"
#include "editor/node_canvas.h"
#include "editor/orbit_camera.h"
#include "editor/panel_layout.h"
#include "editor/script_input.h"
#include "editor/script_runner.h"
#include "nodes/registry.h"
#include "runtime/glfw_context.h"
#include "runtime/scene.h"

namespace wg::editor {

using Clock = std::chrono::steady_clock;

inline double msBetween(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); }

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

class EditorWindow : private ScriptHost {
 public:
  EditorWindow(const EditorOptions& options, rt::GlfwContext& window)
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
      settings_ = loadEditorSettings(settingsPath_);
  }

  int run();

 private:
  static rt::RenderSettings previewSettings(int w, int h, int grid) {
    rt::RenderSettings s;
    s.width = w, s.height = h;
    s.waterGridQuads = grid;
    s.animation = true;  // the preview's frames follow one another: the ocean's foam continues its steps
    return s;
  }

  // --- model and files ---
  bool loadFromDisk(bool initial);
  // Before another file is loaded in this window (a subgraph opened, a file opened): the
  // graph, what was read from disk, the canvas and the selection start empty.
  void forgetGraph() {
    editor_ = GraphEditor(Graph{}, &registry_);
    haveGraph_ = false;
    diskText_.clear();
    diskRevision_ = -1;
    canvas_ = NodeCanvas{};
    selected_.clear();
  }
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
  std::string saveAs(const std::string& path) override;
  // Edits the graph at `path` instead (the editor's top-level file); refused while the
  // current one has unsaved changes unless `discard`, and while a subgraph is open.
  std::string open(const std::string& path, bool discard) override;
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
  void drawRecentFiles();
  std::string recentConfirm_;  // a recent file chosen while this one has unsaved changes
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
  bool buoys_ = false;  // float the built-in scene's buoys on the preview's water
  bool previewDirty_ = true;
  double frameMs_ = 0;
  PendingLatency pending_;
  std::optional<Latency> lastLatency_;

  NodeCanvas canvas_;
  std::array<char, 1024> saveAsPath_{};  // the save-as dialog's path field
  std::string saveAsRefusal_;
  EditorSettings settings_;   // the splitters' positions, the graphs opened last
  std::string settingsPath_;  // where they are remembered ("" : not remembered)
  void rememberSettings();    // writes settings_ (when there is a settings file)
  void rememberOpened(const std::string& path) { settings_.opened(path), rememberSettings(); }
  std::string openRecentRequest_;  // a recent file chosen in the UI, opened between frames
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

}  // namespace wg::editor
