#pragma once
// The watergraph subcommands. Each registers its options on the CLI11 app and returns the
// process exit code when run: 0 success, 1 graph or validation errors, 2 usage or I/O.
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/diagnostic.h"

namespace wg::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitGraphError = 1;
inline constexpr int kExitUsageOrIo = 2;

struct GlobalOptions {
  std::string diagnosticsFormat = "text";  // text | json | sarif
};

using Runner = std::function<int()>;

Runner addCompileCommand(CLI::App& app, const GlobalOptions& global);
Runner addValidateCommand(CLI::App& app, const GlobalOptions& global);
Runner addNodesCommand(CLI::App& app, const GlobalOptions& global);
Runner addFmtCommand(CLI::App& app, const GlobalOptions& global);
Runner addRenderCommand(CLI::App& app, const GlobalOptions& global);
Runner addSchemaCommand(CLI::App& app, const GlobalOptions& global);
Runner addProbeCommand(CLI::App& app, const GlobalOptions& global);
Runner addCheckCommand(CLI::App& app, const GlobalOptions& global);
Runner addBenchCommand(CLI::App& app, const GlobalOptions& global);
Runner addSceneCommand(CLI::App& app, const GlobalOptions& global);
Runner addTuneCommand(CLI::App& app, const GlobalOptions& global);
Runner addCodesCommand(CLI::App& app, const GlobalOptions& global);

// Prints diagnostics in the chosen format (text to stderr, JSON to stdout; SARIF to stdout,
// a complete log even when there are none).
void printDiagnostics(const Diagnostics& diags, const GlobalOptions& global);
// Exit code for a failed run: I/O problems (WG05x) are 2, graph problems 1.
int exitCodeFor(const Diagnostics& diags);

}  // namespace wg::cli
