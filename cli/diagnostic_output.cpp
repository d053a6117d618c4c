#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/commands.h"

namespace wg::cli {

void printDiagnostics(const Diagnostics& diags, const GlobalOptions& global) {
  if (diags.empty()) return;
  if (global.diagnosticsFormat == "json") {
    nlohmann::json all = nlohmann::json::array();
    for (const auto& d : diags.sorted()) all.push_back(toJson(d));
    std::cout << nlohmann::json{{"diagnostics", all}}.dump(2) << "\n";
    return;
  }
  for (const auto& d : diags.sorted()) std::cerr << formatText(d) << "\n";
}

int exitCodeFor(const Diagnostics& diags) {
  bool graphError = false;
  for (const auto& d : diags.all()) {
    if (d.severity != Severity::Error) continue;
    if (d.code != DiagCode::FileRead && d.code != DiagCode::FileWrite) graphError = true;
  }
  return graphError ? kExitGraphError : kExitUsageOrIo;
}

}  // namespace wg::cli
