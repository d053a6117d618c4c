// fmt: rewrites graphs in the canonical form (atomically), or checks that they are.
#include <filesystem>
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
      // One read: the bytes compared and the graph formatted are the same snapshot (a
      // second read could see another version of the file, or block on a FIFO).
      auto current = readGraphFile(path, diags);
      std::optional<Graph> graph;
      if (current) graph = parseGraph(*current, path, diags);
      if (!graph) {
        all.append(diags);
        continue;
      }
      std::string canonical = saveGraph(*graph);
      if (*current == canonical) continue;
      if (args->check) {
        std::cout << path << ": not in canonical form (run: watergraph fmt " << path << ")\n";
        ++unformatted;
        continue;
      }
      // The file changed since it was read (an editor saved it): formatting the old
      // snapshot would lose that edit. Checked again right before the rename.
      // (Only a regular file: a FIFO would block; writeFileAtomically refuses the rest.)
      bool changed = false;
      std::error_code fec;
      if (std::filesystem::is_regular_file(path, fec)) {
        Diagnostics recheck;
        auto now = readGraphFile(path, recheck);
        changed = !now || *now != *current;
      }
      if (changed) {
        diags.error(DiagCode::FileWrite, SourceRef{path, 0, 0},
                    "the file changed while it was being formatted; left as it is (run fmt again)");
      } else if (writeFileAtomically(realPathForRewrite(path), canonical, diags)) {
        std::cout << "formatted " << path << "\n";
      }
      all.append(diags);
    }
    printDiagnostics(all, global);
    if (all.hasErrors()) return exitCodeFor(all);
    return unformatted ? kExitGraphError : kExitOk;
  };
}

}  // namespace wg::cli
