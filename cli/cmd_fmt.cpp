// fmt: rewrites graphs in the canonical form (atomically), or checks that they are.
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "codegen/output_files.h"
#include "core/graph_io.h"

namespace wg::cli {

Runner addFmtCommand(CLI::App& app, const GlobalOptions& global) {
  struct Args {
    std::vector<std::string> graphs;
    bool check = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "fmt",
      "Rewrite graph files in the canonical form: stable key order, stable number formatting, LF line endings.\n\n"
      "Examples:\n  watergraph fmt graphs/lake.json\n  watergraph fmt --check graphs/*.json");
  cmd->add_option("graphs", args->graphs, "graph files (.json)")->required();
  cmd->add_flag("--check", args->check, "change nothing; exit 1 if a file is not in canonical form");
  return [args, &global] {
    Diagnostics all;
    int unformatted = 0;
    for (const auto& path : args->graphs) {
      Diagnostics diags;
      auto graph = loadGraphFile(path, diags);
      if (!graph) {
        all.append(diags);
        continue;
      }
      std::string canonical = saveGraph(*graph);
      std::string current;
      {
        // Re-read the bytes to compare: loadGraphFile does not keep them.
        FILE* f = std::fopen(path.c_str(), "rb");
        if (f) {
          char buf[65536];
          size_t n;
          while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) current.append(buf, n);
          std::fclose(f);
        }
      }
      if (current == canonical) continue;
      if (args->check) {
        std::cout << path << ": not in canonical form (run: watergraph fmt " << path << ")\n";
        ++unformatted;
        continue;
      }
      if (writeFileAtomically(path, canonical, diags)) std::cout << "formatted " << path << "\n";
      all.append(diags);
    }
    printDiagnostics(all, global);
    if (all.hasErrors()) return exitCodeFor(all);
    return unformatted ? kExitGraphError : kExitOk;
  };
}

}  // namespace wg::cli
