#include "eco_support.h"

#include <cstdlib>

namespace wg::eco {

bool haveTool(const std::string& tool) { return sh("command -v " + test::shellQuote(tool)).exit == 0; }

std::string debianPython() {
  std::error_code ec;
  if (std::filesystem::exists("/usr/bin/python3", ec)) return "/usr/bin/python3";
  return "python3";
}

TempDir::TempDir(const std::string& prefix) : path_(test::makeTempDir(prefix)) {}

TempDir::~TempDir() {
  if (std::getenv("WG_KEEP_TEMP")) return;
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

}  // namespace wg::eco
