#pragma once
// Runs an edit script (editor/edit_script.h) one step per frame against whatever shows the
// graph: the window app, or a test's stand-in. What a step needs from its host (the graph
// editor, saving, the previews, the camera) goes through ScriptHost; the waiting (frames,
// a reload noticed on disk) and the order of steps live here, without any UI.
#include <string>
#include <vector>

#include "core/graph_edit.h"
#include "editor/edit_script.h"

namespace wg::editor {

class ScriptHost {
 public:
  virtual ~ScriptHost() = default;
  virtual bool graphLoaded() const = 0;
  virtual GraphEditor& graphEditor() = 0;
  virtual void edited() = 0;  // a step changed the graph: the edit-to-pixels clock starts
  virtual const std::string& graphPath() const = 0;  // the file being edited (a subgraph's, when one is open)
  virtual int diskEvents() const = 0;  // changes on disk noticed so far
  // Each returns "" on success, else why not.
  virtual std::string save(const std::string& path) = 0;
  // Saves to `path` and goes on editing that file (the old one stays as it was on disk).
  virtual std::string saveAs(const std::string& path) { return "'save_as' needs the editor (" + path + ")"; }
  // Edits another graph file instead (open, open recent).
  virtual std::string open(const std::string& path, bool discard) {
    return "'open' needs the editor (" + path + (discard ? ", discarding)" : ")");
  }
  virtual std::string screenshot(const std::string& path) = 0;  // the window, after this frame
  virtual std::string savePreview(const std::string& path) = 0;
  virtual std::string saveThumbnail(const std::string& path) = 0;
  virtual std::string select(const std::string& node, int port) = 0;
  virtual std::string camera(const std::string& preset) = 0;
  virtual void setTime(float seconds) = 0;
  // Edits the subgraph file of instance node `node` instead, until back().
  virtual std::string openSubgraph(const std::string& node) = 0;
  // Back to the graph the open subgraph was opened from, compiled again with the
  // subgraph as it is on disk; refused while the subgraph has unsaved changes unless
  // `discard`.
  virtual std::string back(bool discard) = 0;
  // Keys and pointer as a person gives them ("key", "type", "click", "drag", "wheel";
  // editor/script_input.h); a host without a window takes none.
  virtual std::string input(const ScriptStep& step) { return "'" + step.op + "' needs the editor's window"; }
  // The pointer frames of the last input step are still being played.
  virtual bool inputPending() const { return false; }
};

class ScriptRunner {
 public:
  // `name` (the script's path) prefixes every message.
  ScriptRunner(std::vector<ScriptStep> steps, std::string name) : steps_(std::move(steps)), name_(std::move(name)) {}

  // Called once per frame: runs the next step unless one is waiting. False when a step
  // failed; `error()` then says which and why.
  bool step(ScriptHost& host);
  // Every step has run and nothing waits.
  bool done() const { return next_ >= steps_.size() && waitFrames_ == 0 && waitReloadFrom_ < 0; }
  const std::string& error() const { return error_; }

  // Frames a "wait_reload" waits for the change on disk before the script fails.
  static constexpr int kReloadFrames = 600;

 private:
  bool run(ScriptHost& host, const ScriptStep& step);
  bool fail(const std::string& where, const std::string& why);

  std::vector<ScriptStep> steps_;
  std::string name_;
  size_t next_ = 0;
  int waitFrames_ = 0;
  int waitReloadFrom_ = -1;     // diskEvents() to exceed, while waiting for a reload
  int waitReloadBudget_ = 0;
  int eventsBeforeWrite_ = -1;  // diskEvents() when the script last wrote the file
  std::string error_;
};

}  // namespace wg::editor
