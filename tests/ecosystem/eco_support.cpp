#include "eco_support.h"

#include <cstdlib>

#include "core/node_spec.h"
#include "nodes/registry.h"

namespace wg::eco {

bool haveTool(const std::string& tool) { return sh("command -v " + test::shellQuote(tool)).exit == 0; }

std::string debianPython() {
  std::error_code ec;
  if (std::filesystem::exists("/usr/bin/python3", ec)) return "/usr/bin/python3";
  return "python3";
}

nlohmann::json halfResolutionGraph(const std::string& name, int* scaled) {
  nlohmann::json graph = nlohmann::json::parse(test::readFile(test::sourcePath("graphs/" + name + ".json")));
  *scaled = 0;
  for (auto& node : graph["nodes"]) {
    const NodeSpec* spec = defaultRegistry().find(node["type"].get<std::string>());
    if (!spec || spec->optionIndex(kResolutionOption) < 0) continue;
    node["options"][kResolutionOption] = 0.5;
    ++*scaled;
  }
  return graph;
}

TempDir::TempDir(const std::string& prefix) : path_(test::makeTempDir(prefix)) {}

TempDir::~TempDir() {
  if (std::getenv("WG_KEEP_TEMP")) return;
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

}  // namespace wg::eco
