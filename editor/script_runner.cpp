#include "editor/script_runner.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "editor/widget_rects.h"
#include "nodes/registry.h"

namespace wg::editor {

bool ScriptRunner::fail(const std::string& where, const std::string& why) {
  error_ = where.empty() ? name_ + ": " + why : where + ": " + why;
  return false;
}

bool ScriptRunner::step(ScriptHost& host) {
  if (host.inputPending()) return true;  // a click or drag takes several frames
  if (waitFrames_ > 0) {
    --waitFrames_;
    return true;
  }
  if (waitReloadFrom_ >= 0) {
    if (host.diskEvents() > waitReloadFrom_) {
      waitReloadFrom_ = -1;
    } else {
      if (--waitReloadBudget_ <= 0) return fail("", "wait_reload: the change on disk was not noticed");
      return true;
    }
  }
  if (next_ >= steps_.size()) return true;
  return run(host, steps_[next_++]);
}

bool ScriptRunner::run(ScriptHost& host, const ScriptStep& step) {
  const auto& a = step.args;
  const std::string where = name_ + ": step " + std::to_string(step.index) + " (" + step.op + ")";
  auto done = [&](const std::string& why) { return why.empty() || fail(where, why); };
  auto str = [&](const char* key) -> std::string {
    auto it = a.find(key);
    return it != a.end() && it->is_string() ? it->get<std::string>() : "";
  };
  if (isEditOp(step.op)) {
    if (!host.graphLoaded()) return fail(where, "the graph has not loaded");
    GraphEditor& editor = host.graphEditor();
    long before = editor.revision();
    EditContext context{&defaultRegistry(), std::filesystem::path(host.graphPath()).parent_path().string()};
    std::string why = applyEditStep(editor, step, context);
    editor.seal();
    if (!why.empty()) return fail(where, why);
    if (editor.revision() != before) host.edited();
    return true;
  }
  if (step.op == "save") return done(host.save(str("path").empty() ? host.graphPath() : str("path")));
  if (step.op == "open") {
    if (str("path").empty()) return fail(where, "needs a string \"path\"");
    if (a.contains("discard") && !a["discard"].is_boolean()) return fail(where, "\"discard\" must be true or false");
    return done(host.open(str("path"), a.value("discard", false)));
  }
  if (step.op == "save_as") {
    if (str("path").empty()) return fail(where, "needs a string \"path\"");
    return done(host.saveAs(str("path")));
  }
  if (step.op == "screenshot" || step.op == "save_preview" || step.op == "save_thumbnail") {
    if (str("path").empty()) return fail(where, "needs a string \"path\"");
    if (step.op == "screenshot") return done(host.screenshot(str("path")));
    if (step.op == "save_thumbnail") return done(host.saveThumbnail(str("path")));
    return done(host.savePreview(str("path")));
  }
  if (step.op == "select") {
    int port = a.contains("port") && a["port"].is_number_integer() ? a["port"].get<int>() : 0;
    return done(host.select(str("node"), port));
  }
  if (step.op == "camera") return done(host.camera(str("preset")));
  if (step.op == "time") {
    if (!a.contains("value") || !a["value"].is_number()) return fail(where, "needs a number \"value\"");
    host.setTime(a["value"].get<float>());
    return true;
  }
  if (step.op == "frames") {
    waitFrames_ = a.contains("count") && a["count"].is_number_integer() ? a["count"].get<int>() : 1;
    return true;
  }
  if (step.op == "key" || step.op == "type" || step.op == "click" || step.op == "drag" || step.op == "wheel" ||
      step.op == "hover" || step.op == "set_clipboard" || step.op == "save_clipboard")
    return done(host.input(step));
  if (step.op == "print_widgets") {
    // Where the named widgets were drawn in the last frame, for a test to measure.
    for (const auto& [name, r] : widgetRects().all())
      if (name.rfind(str("prefix"), 0) == 0)
        std::cout << "widget " << name << ": " << r[0] << " " << r[1] << " " << r[2] << " " << r[3] << std::endl;
    return true;
  }
  if (step.op == "open_subgraph") return done(host.openSubgraph(str("node")));
  if (step.op == "back") {
    if (a.contains("discard") && !a["discard"].is_boolean()) return fail(where, "\"discard\" must be true or false");
    return done(host.back(a.value("discard", false)));
  }
  if (step.op == "external_write") {
    // Another program writing the graph file (or, with "path", another file such as an
    // imported one) in place, as a text editor does.
    std::string text = str("text");
    if (!str("from").empty()) {
      std::ifstream in(str("from"), std::ios::binary);
      if (!in) return fail(where, "cannot read " + str("from"));
      std::stringstream ss;
      ss << in.rdbuf();
      text = ss.str();
    }
    std::string path = str("path").empty() ? host.graphPath() : str("path");
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
    if (!out) return fail(where, "cannot write " + path);
    eventsBeforeWrite_ = host.diskEvents();
    return true;
  }
  if (step.op == "wait_reload") {
    // The change may already have been noticed in the frame after the write.
    waitReloadFrom_ = eventsBeforeWrite_ >= 0 ? eventsBeforeWrite_ : host.diskEvents();
    eventsBeforeWrite_ = -1;
    waitReloadBudget_ = kReloadFrames;
    return true;
  }
  return fail(where, "unknown op");
}

}  // namespace wg::editor
