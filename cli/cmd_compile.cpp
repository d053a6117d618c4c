// compile: graphs -> GLSL files + manifest; validate: the same checks, nothing written.
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

#include <unistd.h>

#include "cli/commands.h"
#include "codegen/compile.h"
#include "codegen/output_files.h"
#include "core/graph_io.h"
#include "nodes/registry.h"

namespace wg::cli {
namespace {

struct CompileArgs {
  std::vector<std::string> graphs;
  std::string outDir;
  std::vector<std::string> targets;
  bool subdirs = false;
  bool summary = false;
};

bool parseTargets(const std::vector<std::string>& names, std::vector<Target>& out) {
  out.clear();
  for (const auto& n : names) {
    std::stringstream ss(n);
    std::string part;
    while (std::getline(ss, part, ',')) {
      auto t = parseTarget(part);
      if (!t) {
        std::cerr << "watergraph: unknown target '" << part << "' (glsl330, es300, vk450)\n";
        return false;
      }
      bool dup = false;
      for (Target have : out) dup |= have == *t;
      if (!dup) out.push_back(*t);
    }
  }
  if (out.empty()) out = allTargets();
  return true;
}

struct GraphOutcome {
  std::string name;
  int kept = 0, total = 0;
  bool ok = false;
  size_t errors = 0;
};

void printSummary(const std::vector<GraphOutcome>& outcomes, const std::vector<Target>& targets) {
  std::string targetList;
  for (Target t : targets) targetList += (targetList.empty() ? "" : ",") + std::string(targetName(t));
  size_t w = 5;
  for (const auto& o : outcomes) w = std::max(w, o.name.size());
  std::printf("%-*s  %-11s  %-21s  %s\n", static_cast<int>(w), "graph", "nodes", "targets", "status");
  std::printf("%s\n", std::string(w + 2 + 11 + 2 + 21 + 2 + 16, '-').c_str());
  int failed = 0;
  for (const auto& o : outcomes) {
    std::string nodes = o.total ? std::to_string(o.kept) + "/" + std::to_string(o.total) : "-";
    std::string status = o.ok ? "ok" : "FAILED (" + std::to_string(o.errors) + " error" + (o.errors == 1 ? "" : "s") + ")";
    std::printf("%-*s  %-11s  %-21s  %s\n", static_cast<int>(w), o.name.c_str(), nodes.c_str(), targetList.c_str(),
                status.c_str());
    failed += !o.ok;
  }
  std::printf("%zu graph%s, %d failed\n", outcomes.size(), outcomes.size() == 1 ? "" : "s", failed);
}

int runCompile(const CompileArgs& args, const GlobalOptions& global, bool write) {
  std::vector<Target> targets;
  if (!parseTargets(args.targets, targets)) return kExitUsageOrIo;
  const Registry& registry = defaultRegistry();
  Diagnostics all;
  std::vector<GraphOutcome> outcomes;
  for (const auto& path : args.graphs) {
    Diagnostics diags;
    GraphOutcome outcome;
    outcome.name = graphBaseName(path);
    auto graph = loadGraphFile(path, diags);
    std::optional<CompileResult> result;
    if (graph) {
      CompileOptions options;
      options.targets = targets;
      result = compileGraph(*graph, registry, options, diags);
      outcome.total = static_cast<int>(graph->nodes.size());
    }
    if (result) {
      outcome.kept = result->nodesKept;
      if (write) {
        std::string dir = args.subdirs ? args.outDir + "/" + outcome.name : args.outDir;
        outcome.ok = writeOutputFiles(dir, result->files, diags);
      } else {
        outcome.ok = true;
      }
    }
    outcome.errors = diags.errorCount();
    all.append(diags);
    outcomes.push_back(outcome);
  }
  printDiagnostics(all, global);
  if (args.summary) printSummary(outcomes, targets);
  if (!all.hasErrors()) {
    if (!write && !args.summary)
      std::cout << "validated " << args.graphs.size() << " graph" << (args.graphs.size() == 1 ? "" : "s") << " for "
                << targets.size() << " target" << (targets.size() == 1 ? "" : "s") << ": ok\n";
    return kExitOk;
  }
  return exitCodeFor(all);
}

}  // namespace

Runner addCompileCommand(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<CompileArgs>();
  CLI::App* cmd = app.add_subcommand(
      "compile",
      "Compile graphs to GLSL (and SPIR-V for vk450) plus a manifest; every shader is validated by glslang first "
      "and nothing is written for a graph that fails.\n\nExamples:\n"
      "  watergraph compile graphs/lake.json -o out\n"
      "  watergraph compile graphs/*.json -o out --subdirs --summary\n"
      "  watergraph compile graphs/lake.json -o out --target es300");
  cmd->add_option("graphs", args->graphs, "graph files (.json)")->required();
  cmd->add_option("-o,--output", args->outDir, "output folder")->required();
  cmd->add_option("--target", args->targets, "targets, comma separated: glsl330, es300, vk450 (default: all)");
  cmd->add_flag("--subdirs", args->subdirs, "write each graph into OUTPUT/<graph>/");
  cmd->add_flag("--summary", args->summary, "print a table: graph, nodes kept/total, targets, status");
  return [args, &global] { return runCompile(*args, global, true); };
}

Runner addValidateCommand(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<CompileArgs>();
  CLI::App* cmd = app.add_subcommand(
      "validate",
      "Compile graphs for every target and validate them with glslang without writing anything: exit 0 when all "
      "pass, 1 with one line per failure.\n\nExamples:\n  watergraph validate graphs/*.json\n"
      "  watergraph validate graphs/lake.json --diagnostics-format json");
  cmd->add_option("graphs", args->graphs, "graph files (.json)")->required();
  cmd->add_option("--target", args->targets, "targets, comma separated (default: all)");
  return [args, &global] { return runCompile(*args, global, false); };
}

}  // namespace wg::cli
