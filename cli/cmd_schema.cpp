// schema: the JSON Schema of graph files, generated from the node registry
// (docs/watergraph.schema.json).
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "cli/option_values.h"
#include "codegen/output_files.h"
#include "nodes/graph_schema.h"
#include "nodes/registry.h"

namespace wg::cli {

Runner addSchemaCommand(CLI::App& app, const GlobalOptions& global) {
  struct Args {
    std::string output;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "schema",
      "Print the JSON Schema (draft-07) of graph files, generated from the node registry: node types, their input "
      "ports and options (choices, ranges, texture sources), parameters and output slots. Graphs that name it with "
      "\"$schema\" get completion and checking in editors such as VS Code.\n\nExamples:\n"
      "  watergraph schema > docs/watergraph.schema.json\n"
      "  watergraph schema -o docs/watergraph.schema.json\n"
      "  python3 -m jsonschema -i graphs/lake.json docs/watergraph.schema.json");
  addOutputOption(cmd, "-o,--output", args->output, "write the schema to this file (atomically) instead of stdout");
  return [args, &global] {
    std::string text = graphSchemaText(defaultRegistry());
    if (args->output.empty()) {
      std::cout << text;
      return kExitOk;
    }
    Diagnostics diags;
    if (!writeFileAtomically(args->output, text, diags)) {
      printDiagnostics(diags, global);
      return exitCodeFor(diags);
    }
    return kExitOk;
  };
}

}  // namespace wg::cli
