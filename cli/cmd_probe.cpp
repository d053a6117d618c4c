// probe: one output of a graph evaluated per case on the GPU in float32 (one pixel of an
// RGBA32F target per case) and by the double reference; prints both, the errors and the
// NaN/Inf flags. Exit 1 when a case is NaN/Inf, out of its range or over its tolerance.
#include <iostream>
#include <memory>

#include "cli/commands.h"

#ifdef WG_HAVE_RUNTIME
#include "accuracy/hard_case_suite.h"
#include "accuracy/probe.h"
#include "nodes/registry.h"
#include "core/graph_io.h"
#include "runtime/egl_context.h"
#include "runtime/preview.h"
#include "runtime/runtime_error.h"
#endif

namespace wg::cli {
namespace {

struct ProbeArgs {
  std::string graph;
  std::string output;
  std::string cases;
  std::string target = "glsl330";
  bool json = false;
  std::string node;       // probe a node type alone, as the hard-case suite does
  bool variants = false;  // with --node: every option variant too
};

#ifdef WG_HAVE_RUNTIME
// --node TYPE: the cases that apply to the node (a port they set, a builtin it reads), each
// output, grouped by the options the cases give it; the suite's code path.
int runNodeProbe(const ProbeArgs& args, const GlobalOptions& global, Target target) {
  const NodeSpec* spec = defaultRegistry().find(args.node);
  if (!spec) {
    std::cerr << "watergraph: --node: no node type '" << args.node << "' (see watergraph nodes)\n";
    return kExitUsageOrIo;
  }
  Diagnostics diags;
  auto cases = accuracy::loadProbeCases(args.cases, diags);
  printDiagnostics(diags, global);
  if (!cases) return exitCodeFor(diags);
  try {
    auto context = rt::EglContext::create(rt::apiFor(target));
    accuracy::SuiteOptions options;
    options.nodes = {spec->type};
    options.variants = args.variants;
    accuracy::SuiteResult r = accuracy::runHardCaseSuite(*cases, target, options);
    nlohmann::json all = nlohmann::json::array();
    for (const auto& run : r.runs) {
      if (args.json) {
        nlohmann::json j = accuracy::probeJson(run.report);
        j["variant"] = run.variant;
        all.push_back(j);
      } else {
        std::cout << "[" << run.variant << "] " << accuracy::formatProbeText(run.report);
      }
    }
    if (args.json) std::cout << all.dump(2) << "\n";
    for (const auto& e : r.errors) std::cerr << "watergraph: probe: " << e << "\n";
    std::cerr << r.caseRuns << " case runs, " << r.failures << " failed (" << r.nanInf << " NaN/Inf)\n";
    return r.failures || !r.errors.empty() ? kExitGraphError : kExitOk;
  } catch (const rt::RuntimeError& e) {
    std::cerr << "watergraph: probe: " << e.what() << "\n";
    return e.exitCode();
  }
}

int runProbe(const ProbeArgs& args, const GlobalOptions& global) {
  if (args.node.empty() == args.graph.empty()) {
    std::cerr << "watergraph: probe needs a GRAPH or --node TYPE (one of them)\n";
    return kExitUsageOrIo;
  }
  if (!args.node.empty()) return runNodeProbe(args, global, *parseTarget(args.target));
  ProbeOutput output;
  if (!args.output.empty()) {
    auto o = parseProbeOutput(args.output);
    if (!o) {
      std::cerr << "watergraph: --output must be NODE or NODE.PORT (got '" << args.output << "')\n";
      return kExitUsageOrIo;
    }
    output = *o;
  }
  Target target = *parseTarget(args.target);
  Diagnostics diags;
  auto graph = loadGraphFile(args.graph, diags);
  auto cases = accuracy::loadProbeCases(args.cases, diags);
  if (!graph || !cases) {
    printDiagnostics(diags, global);
    return exitCodeFor(diags);
  }
  try {
    auto context = rt::EglContext::create(rt::apiFor(target));
    auto report = accuracy::probeGraph(*graph, output, *cases, target, diags);
    printDiagnostics(diags, global);
    if (!report) return exitCodeFor(diags);
    if (args.json) std::cout << accuracy::probeJson(*report).dump(2) << "\n";
    else std::cout << accuracy::formatProbeText(*report);
    return report->passed() ? kExitOk : kExitGraphError;
  } catch (const rt::RuntimeError& e) {
    std::cerr << args.graph << ": error: " << e.what() << "\n";
    return e.exitCode();
  }
}
#endif

}  // namespace

Runner addProbeCommand(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<ProbeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "probe",
      "Evaluate one output of a graph per case on the GPU in float32 (headless GL, one pixel of an RGBA32F target per "
      "case) and with the double reference; print GPU value, reference, absolute and relative error and NaN/Inf flags. "
      "A case sets the builtins (uv, world_position, normal, view_direction, time, camera, screen_uv, frag_depth, "
      "near_far), the scene textures' values and parameters; see docs/accuracy.md.\n\nExamples:\n"
      "  watergraph probe graphs/lake.json --cases tests/hardcases/lake.json\n"
      "  watergraph probe graphs/lake.json --output fresnel.reflectance --cases cases.json --target es300 --json\n"
      "  watergraph probe --node fresnel --cases tests/hardcases/suite.json --variants\n\n"
      "Exit codes: 0 every case finite and within tolerance; 1 a NaN/Inf, a range or tolerance failure, or graph/case "
      "errors; 2 usage, I/O, or no EGL/GL context.");
  cmd->add_option("graph", args->graph, "graph file (.json); or --node");
  cmd->add_option("--output", args->output, "the node output to probe, NODE.PORT (default: the fragment colour)");
  cmd->add_option("--cases", args->cases, "cases file (.json), see docs/accuracy.md")->required();
  cmd->add_option("--target", args->target, "glsl330 (OpenGL 4.5 core) or es300 (OpenGL ES 3.2)")
      ->check(CLI::IsMember({"glsl330", "es300"}))
      ->capture_default_str();
  cmd->add_flag("--json", args->json, "print the results as JSON on stdout");
  cmd->add_option("--node", args->node,
                  "probe a node type alone, every output, with the cases that apply to it (they may set \"inputs\", "
                  "\"options\" and \"ranges\"), as the hard-case suite does");
  cmd->add_flag("--variants", args->variants, "with --node: also every variant of its options");
#ifdef WG_HAVE_RUNTIME
  return [args, &global] { return runProbe(*args, global); };
#else
  return [] {
    std::cerr << "watergraph: probe: this build has no GL runtime (configure with -DWG_BUILD_RUNTIME=ON)\n";
    return kExitUsageOrIo;
  };
#endif
}

}  // namespace wg::cli
