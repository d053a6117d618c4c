// watergraph-editor GRAPH: the live editor (docs/editor.md). Parses the command line and
// hands over to runEditor.
#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>

#include "core/frame_size_text.h"
#include "cli/finite_number.h"
#include "codegen/output_files.h"
#include "core/diagnostic.h"
#include "core/graph.h"
#include "editor/editor_app.h"
#include "editor/graph_template.h"
#include "runtime/scene.h"

namespace {

bool parseSize(const std::string& text, int* w, int* h) {
  const auto size = wg::parseFrameSizeText(text, 16, 8192);
  if (!size) return false;
  *w = size->width, *h = size->height;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  wg::editor::EditorOptions o;
  std::string windowSize = "1280x720", previewSize = "640x360";
  float time = 0;
  CLI::App app("watergraph-editor: edit a water graph with a live preview (docs/editor.md)", "watergraph-editor");
  app.add_option("graph", o.graphPath, "the graph file (JSON, format v1)")->required();
  app.add_option("--size", windowSize, "window size WIDTHxHEIGHT (default 1280x720)");
  app.add_option("--preview-size", previewSize, "size the preview renders at (default 640x360)");
  app.add_option("--camera", o.camera, "starting camera preset: above, grazing, underwater, topdown");
  auto* timeOpt = app.add_option("--time", time, "start paused at this time in seconds")->check(wg::cli::finiteFloat());
  app.add_option("--script", o.script, "apply the edits in this JSON file (a list of steps), then exit");
  app.add_option("--screenshot", o.screenshot, "write the window as a PNG after the last frame, then exit");
  app.add_option("--frames", o.frames, "run this many frames (after the script), then exit");
  app.add_flag("--stats", o.stats, "print each edit's edit-to-pixels latency");
  app.add_flag("--new", o.newGraph, "create the graph file from a small template (it must not exist yet), then edit it");
  app.add_option("--settings", o.settings,
                 "remember panel sizes in this file (default: ~/.config/watergraph/editor.json; batch runs: none)");
  wg::cli::addViewFlags(&app, o.view);
  // A usage error is one line naming the option, as watergraph's.
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return "watergraph-editor: " + std::string(e.what()) + "\n";
  });
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  if (!parseSize(windowSize, &o.windowWidth, &o.windowHeight) || !parseSize(previewSize, &o.previewWidth, &o.previewHeight)) {
    std::cerr << "watergraph-editor: sizes are WIDTHxHEIGHT, each side 16..8192, e.g. 1280x720\n";
    return 2;
  }
  if (!wg::rt::cameraPreset(o.camera)) {
    std::cerr << "watergraph-editor: unknown camera preset '" << o.camera << "' (above, grazing, underwater, topdown)\n";
    return 2;
  }
  if (*timeOpt) o.time = time;
  if (o.frames < 0) {
    std::cerr << "watergraph-editor: --frames must be 0 or more\n";
    return 2;
  }
  if (!o.screenshot.empty() && o.frames == 0 && o.script.empty()) o.frames = 3;  // a screenshot means a batch run
  std::error_code ec;
  if (o.newGraph) {
    // The template, named after the file, written before the window opens: the editor then
    // edits an ordinary file.
    if (std::filesystem::exists(o.graphPath, ec)) {
      std::cerr << "watergraph-editor: --new: " << o.graphPath << " exists already; open it without --new\n";
      return 2;
    }
    std::string stem = std::filesystem::path(o.graphPath).stem().string();
    wg::Diagnostics d;
    if (!wg::writeFileAtomically(o.graphPath, wg::editor::newGraphText(wg::isIdentifier(stem) ? stem : "new_graph"), d)) {
      for (const auto& e : d.all()) std::cerr << wg::formatText(e) << "\n";
      return 2;
    }
  }
  if (!std::filesystem::is_regular_file(o.graphPath, ec)) {
    std::cerr << o.graphPath << ": error: [WG050] cannot open the graph file: no such file (--new creates one)\n";
    return 2;
  }
  return wg::editor::runEditor(o);
}
