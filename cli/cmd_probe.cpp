// probe: one output of a graph evaluated per case on the GPU in float32 (one pixel of an
// RGBA32F target per case) and by the double reference; prints both, the errors and the
// NaN/Inf flags. Exit 1 when a case is NaN/Inf, out of its range or over its tolerance.
#include <iostream>
#include <memory>

#include "cli/commands.h"

#ifdef WG_HAVE_RUNTIME
#include "accuracy/probe.h"
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
};

#ifdef WG_HAVE_RUNTIME
int runProbe(const ProbeArgs& args, const GlobalOptions& global) {
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
      "  watergraph probe graphs/lake.json --output fresnel.reflectance --cases cases.json --target es300 --json\n\n"
      "Exit codes: 0 every case finite and within tolerance; 1 a NaN/Inf, a range or tolerance failure, or graph/case "
      "errors; 2 usage, I/O, or no EGL/GL context.");
  cmd->add_option("graph", args->graph, "graph file (.json)")->required();
  cmd->add_option("--output", args->output, "the node output to probe, NODE.PORT (default: the fragment colour)");
  cmd->add_option("--cases", args->cases, "cases file (.json), see docs/accuracy.md")->required();
  cmd->add_option("--target", args->target, "glsl330 (OpenGL 4.5 core) or es300 (OpenGL ES 3.2)")
      ->check(CLI::IsMember({"glsl330", "es300"}))
      ->capture_default_str();
  cmd->add_flag("--json", args->json, "print the results as JSON on stdout");
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
