#pragma once
// Running watergraph-editor as a user would, without a person: under xvfb-run, with
// scripted edits (--script). Shared by the editor's test files.
#include <string>

namespace wg::test {

std::string editorBinary();  // next to the watergraph binary

struct EditorRun {
  int status = -1;
  std::string out, err;
};

// Runs the editor with `args` under a virtual X server; Mesa's shader cache stays off
// (tests must not write into the user's cache). The X authority file lives in `dir` (the
// test's folder): with its own temporary folder, xvfb-run sometimes fails to remove it
// and exits 5 instead of passing on the editor's status. Small window and preview sizes
// keep each run to a second or two on llvmpipe.
EditorRun runEditorProgram(const std::string& dir, const std::string& args, const std::string& window = "640x360");

}  // namespace wg::test
