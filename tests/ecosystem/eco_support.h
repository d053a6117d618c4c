#pragma once
// Helpers for the ecosystem suite: running watergraph and other tools, temp folders.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "test_support.h"

namespace wg::eco {

using test::CmdResult;
// Runs `watergraph <args>` (args already shell-quoted where needed).
inline CmdResult wgRun(const std::string& args) { return test::runWatergraph(args); }
// Runs a shell command, stdout and stderr apart.
inline CmdResult sh(const std::string& command) { return test::runSplit(command); }
// True when `tool` is on PATH.
bool haveTool(const std::string& tool);
// Debian's python3 (where apt's python3-jsonschema lives) when present, else python3 on PATH.
std::string debianPython();

// graphs/NAME.json with every node that has a `resolution` option at 0.5 (the scene passes
// at half the frame's size); `scaled` counts those nodes.
nlohmann::json halfResolutionGraph(const std::string& name, int* scaled);

class TempDir {
 public:
  explicit TempDir(const std::string& prefix = "wg_eco_");
  ~TempDir();
  const std::string& path() const { return path_; }
  std::string operator/(const std::string& rel) const { return path_ + "/" + rel; }

 private:
  std::string path_;
};

}  // namespace wg::eco
