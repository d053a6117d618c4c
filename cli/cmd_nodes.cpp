// nodes: the node registry as a list, JSON, or the markdown reference (docs/nodes.md); with
// --graph, the node types that graph files offer or import (subgraphs).
#include <cstdio>
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "core/graph_io.h"
#include "nodes/node_docs.h"
#include "nodes/registry.h"

namespace wg::cli {

namespace {

int printSubgraphTypes(const std::vector<std::string>& paths, bool json, const GlobalOptions& global) {
  Diagnostics diags;
  nlohmann::json all = nlohmann::json::array();
  std::string text;
  for (const auto& path : paths) {
    auto graph = loadGraphFile(path, diags);
    if (!graph) continue;
    auto add = [&](const std::string& type, const Graph& g) {
      if (json) all.push_back(functionGraphJson(type, g));
      else text += functionGraphText(type, g);
    };
    if (graph->interface) add(graph->name, *graph);
    for (const auto& im : graph->imports) add(im.name, *im.graph);
    // Text mode says so rather than printing nothing (JSON: the empty list says it).
    if (!json && !graph->interface && graph->imports.empty())
      text += path + ": no subgraph node types (not a function graph, and it imports none)\n";
  }
  if (diags.hasErrors()) {
    printDiagnostics(diags, global);
    return exitCodeFor(diags);
  }
  if (json) std::cout << all.dump(2) << "\n";
  else std::cout << text;
  return kExitOk;
}

}  // namespace

Runner addNodesCommand(CLI::App& app, const GlobalOptions& global) {
  struct Args {
    bool json = false;
    bool markdown = false;
    std::vector<std::string> graphs;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand("nodes",
                                     "List the node types; with --graph, the subgraph node types of graph files: a "
                                     "function graph's own interface, and the interface of every graph a file "
                                     "imports.\n\nExamples:\n  watergraph nodes\n"
                                     "  watergraph nodes --json\n  watergraph nodes --markdown > docs/nodes.md\n"
                                     "  watergraph nodes --graph graphs/lib/shore_foam.json\n"
                                     "  watergraph nodes --graph graphs/river.json --json");
  auto* json = cmd->add_flag("--json", args->json, "every node's ports, options, formula and hard cases as JSON");
  auto* markdown = cmd->add_flag("--markdown", args->markdown, "the node reference as markdown (docs/nodes.md)");
  markdown->excludes(json);
  cmd->add_option("--graph", args->graphs,
                  "graph files: list the node types they offer (a function graph's interface, under its name) and "
                  "import (under the import's name)")
      ->excludes(markdown);
  return [args, &global] {
    if (!args->graphs.empty()) return printSubgraphTypes(args->graphs, args->json, global);
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
