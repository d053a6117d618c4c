#pragma once
// watergraph-editor: one window (GLFW, desktop GL 4.5 core) with the live preview, the
// inspector, the error panel and the node canvas, over one graph file. See docs/editor.md.
#include <optional>
#include <string>

#include "cli/view_flags.h"

namespace wg::editor {

struct EditorOptions {
  std::string graphPath;
  int windowWidth = 1280, windowHeight = 720;
  int previewWidth = 640, previewHeight = 360;  // the preview's render size
  std::string camera = "above";
  std::optional<float> time;     // set: start paused at this time
  std::string script;            // --script edits.json
  std::string screenshot;        // --screenshot out.png: the window after the last frame
  int frames = 0;                // frames to run (after the script) before exiting; 0: until closed
  bool stats = false;            // print edit-to-pixels latencies to stdout
  cli::ViewFlags view;           // --tonemap / --exposure over the graph's "view"
  bool newGraph = false;         // --new: graphPath does not exist yet; it starts from the template
  std::string settings;          // --settings: where panel sizes are remembered ("": the default; none in batch runs)
};

// Runs the editor. Exit status: 0, 1 when the script failed or the graph (as last
// compiled) has errors, 2 when there is no display or an output file cannot be written.
int runEditor(const EditorOptions& options);

}  // namespace wg::editor
