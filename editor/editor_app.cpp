#include "editor/editor_app.h"
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
// Model and files

bool EditorWindow::loadFromDisk(bool initial) {
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
bool EditorWindow::reloadImports() {
  const bool functionFiles = !functionFilesOf(editor_.graph(), registry_).empty();
  if (editor_.graph().imports.empty() && !functionFiles) return false;
  Graph now = editor_.graph();
  Diagnostics reportedByCompiling;
  loadImports(now, reportedByCompiling);
  editor_.adoptImports(now);
  watcher_.watch(filesToWatch(editor_.graph()));
  recompile();
  status_ = functionFiles ? "imported graphs and function files read again from disk" : "imported graphs read again from disk";
  noteEdit();
  return true;
}

// Compiles the graph again at the next frame, whatever its revision: what it imports changed,
// or another file was shown in the preview.
void EditorWindow::recompile() {
  goodGraph_.reset();
  attemptedRevision_ = -1;
  thumbStale_ = true;
}

bool EditorWindow::writeGraph(const std::string& path) {
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

void EditorWindow::setErrors(const Diagnostics& d, const std::string& context) {
  errors_ = d.sorted();
  errorContext_ = context;
  for (const auto& e : errors_) std::cerr << formatText(e) << "\n";
}

// The graph as loaded keeps the positions of the real file; an edited graph is compiled
// from the text Save would write, so its errors point at lines of that text. Imports are
// loaded again each time, as `watergraph compile` would: the subgraph files as they are
// now, their errors in their own files.
std::optional<Graph> EditorWindow::graphToCompile(Diagnostics& d) const {
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

void EditorWindow::processChange() {
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
        errorContext_ = "warnings: the graph compiles and the preview shows it";
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
    errorContext_ = "warnings: the graph compiles and the preview shows it";
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

void EditorWindow::rebuildThumbnail() {
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
  std::optional<NodePorts> ports = n ? editorPortsOf(editor_.graph(), registry_, *n) : std::nullopt;
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

void EditorWindow::renderPreviews() {
  if (!previewDirty_ && !playing_) return;
  rt::Camera cam = orbit_.toCamera();
  std::string error;
  rt::SceneOptions scene = scene_;
  if (buoys_) scene.buoys = preview_.floatingBuoys(scene.time);
  if (preview_.ready()) frameMs_ = preview_.render(cam, scene, currentView(), &error);
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

void EditorWindow::finishLatency() {
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


int EditorWindow::run() {
  if (!options_.script.empty()) {
    std::string error;
    auto steps = loadScript(options_.script, &error);
    if (!steps) {
      std::cerr << error << "\n";
      return 1;
    }
    script_.emplace(std::move(*steps), options_.script);
  }
  if (loadFromDisk(true)) rememberOpened(path_);

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
    if (!openRecentRequest_.empty()) {
      if (std::string why = open(std::exchange(openRecentRequest_, {}), true); !why.empty()) status_ = why;
    }
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
      EditorWindow app(options, *window);
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
