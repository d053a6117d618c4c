#include "editor_run.h"

#include <filesystem>

#include "test_support.h"

namespace wg::test {

std::string editorBinary() {
  return (std::filesystem::path(watergraphBinary()).parent_path() / "watergraph-editor").string();
}

EditorRun runEditorProgram(const std::string& dir, const std::string& args, const std::string& window) {
  EditorRun r;
  std::string cmd = "xvfb-run -a -f " + shellQuote(dir + "/Xauthority") +
                    " -s '-screen 0 1280x1024x24' " + shellQuote(editorBinary()) + " --size " + window +
                    " --preview-size 320x180 " + args;
  r.status = runCommandSplit(cmd, &r.out, &r.err);
  return r;
}

}  // namespace wg::test
