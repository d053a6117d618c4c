// nodes: the node registry as a list, JSON, or the markdown reference (docs/nodes.md).
#include <cstdio>
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "nodes/node_docs.h"
#include "nodes/registry.h"

namespace wg::cli {

Runner addNodesCommand(CLI::App& app, const GlobalOptions&) {
  struct Args {
    bool json = false;
    bool markdown = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand("nodes",
                                     "List the node types.\n\nExamples:\n  watergraph nodes\n"
                                     "  watergraph nodes --json\n  watergraph nodes --markdown > docs/nodes.md");
  auto* json = cmd->add_flag("--json", args->json, "every node's ports, options, formula and hard cases as JSON");
  cmd->add_flag("--markdown", args->markdown, "the node reference as markdown (docs/nodes.md)")->excludes(json);
  return [args] {
    const Registry& registry = defaultRegistry();
    if (args->json) {
      std::cout << nodesJson(registry).dump(2) << "\n";
    } else if (args->markdown) {
      std::cout << nodesMarkdown(registry);
    } else {
      for (const NodeSpec* s : registry.all())
        std::printf("%-18s %-18s %s\n", s->type.c_str(), s->family.c_str(), s->summary.c_str());
    }
    return kExitOk;
  };
}

}  // namespace wg::cli
