// probe: one output of a graph evaluated per case on the GPU in float32 (one pixel of an
// RGBA32F target per case; GL for glsl330 and es300, Vulkan for vk450, WebGPU in headless
// Chromium for wgsl) and by the double
// reference; prints both, the errors and the
// NaN/Inf flags. Exit 1 when a case is NaN/Inf, out of its range or over its tolerance.
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

#include "cli/commands.h"
#include "cli/option_values.h"
#include "cli/wgsl_checks.h"
#include "cli/wgsl_executor.h"

#ifdef WG_HAVE_RUNTIME
#include "accuracy/function_sweep.h"
#include "accuracy/gpu_executor.h"
#include "accuracy/hard_case_suite.h"
#include "accuracy/node_probe.h"
#include "accuracy/probe.h"
#include "accuracy/sweep.h"
#include "nodes/registry.h"
#include "codegen/emit_wgsl.h"
#include "codegen/output_files.h"
#include "core/graph_io.h"
#include "core/json_source.h"
#include "core/node_options.h"
#include "core/preset.h"
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
  std::string sweep;      // with --node: NAME[.c]:FROM:TO:COUNT
  std::string options;    // with --node --sweep: the node's options, a JSON object
  std::string table;      // with --sweep: where the error curve goes
  std::string mutate;     // FIND=>REPLACE in the probe shader
  std::string preset;     // graph mode: a preset of the graph, applied before probing
  bool vulkanValidation = false;  // vk450: under the Khronos validation layer
  bool functions = false;  // graph mode: sweep the graph's glsl_function nodes over the cases' value classes
};


#ifdef WG_HAVE_RUNTIME
// The executor --target names: GL or Vulkan, or WebGPU through Node.js and headless Chromium
// (clients/webgpu/executor_server.mjs). Throws rt::RuntimeError (Kind::Environment: exit 2)
// naming what is missing when the WebGPU probe cannot run: it did not run, and never passes.
std::unique_ptr<accuracy::GpuExecutor> probeExecutor(const ProbeArgs& args) {
  if (args.target != kWgslTargetName) return accuracy::makeGpuExecutor(*parseTarget(args.target), {args.vulkanValidation});
  return wgslExecutorOrWhyNot("the probe did not run on wgsl: ", {"playwright-core"});
}

// "FIND=>REPLACE" (GLSL has '=' but no "=>").
std::optional<accuracy::ShaderMutation> parseMutation(const std::string& text) {
  auto at = text.find("=>");
  if (at == std::string::npos || at == 0) return std::nullopt;
  return accuracy::ShaderMutation{text.substr(0, at), text.substr(at + 2)};
}

// --node TYPE --sweep AXIS: the first case of --cases (or the default case) repeated along
// the axis, one output, the options given; prints a summary, writes the curve to --table.
int runSweep(const ProbeArgs& args, const GlobalOptions& global, const NodeSpec& spec,
             const accuracy::ShaderMutation& mutation) {
  std::string why;
  auto axis = accuracy::parseSweepAxis(args.sweep, why);
  if (!axis) {
    std::cerr << "watergraph: " << why << "\n";
    return kExitUsageOrIo;
  }
  nlohmann::json options = nlohmann::json::object();
  if (!args.options.empty()) {
    // The graph loader's JSON reader: a key given twice (nlohmann alone keeps the last),
    // a syntax error or runaway nesting is refused as in graph files.
    Diagnostics parsed;
    auto source = parseJsonWithPositions(args.options, "--options", parsed);
    if (!source || parsed.hasErrors() || !source->root.is_object()) {
      std::cerr << "watergraph: --options must be a JSON object (got '" << args.options << "')"
                << (parsed.all().empty() ? "" : ": " + parsed.all().front().message) << "\n";
      return kExitUsageOrIo;
    }
    options = std::move(source->root);
  }
  // The node's ports for these options: an expression's inputs are those --options declares.
  NodePorts ports = portsOfNode(spec, options);
  if (axis->name != "angle" && ports.inputIndex(axis->name) < 0 && !accuracy::isSweepBuiltinKey(axis->name)) {
    std::cerr << "watergraph: --sweep: '" << axis->name << "' is neither 'angle', an input of " << spec.type
              << (spec.portsFor ? " (with these --options)" : "") << " nor a builtin key\n";
    return kExitUsageOrIo;
  }
  accuracy::ProbeCase base;
  base.name = "base";
  base.env = accuracy::defaultProbeEnvironment();
  if (!args.cases.empty()) {
    Diagnostics diags;
    auto cases = accuracy::loadProbeCases(args.cases, diags);
    printDiagnostics(diags, global);
    if (!cases) return exitCodeFor(diags);
    if (!cases->cases.empty()) base = cases->cases.front();
  }
  try {
    auto executor = probeExecutor(args);
    Diagnostics diags;
    auto report = accuracy::probeNode(spec, options, args.output, accuracy::sweepCases(ports, *axis, base), *executor, diags,
                                      mutation);
    executor->finish();
    printDiagnostics(diags, global);
    if (!report) return exitCodeFor(diags);
    double worst = 0, worstAt = axis->from, maxError = 0;
    for (size_t i = 0; i < report->cases.size(); ++i) {
      const auto& c = report->cases[i];
      maxError = std::max(maxError, c.absError);
      double ratio = c.bound > 0 ? c.absError / c.bound : (c.absError > 0 ? INFINITY : 0);
      if (ratio > worst) worst = ratio, worstAt = axis->at(static_cast<int>(i));
    }
    if (!args.table.empty()) {
      Diagnostics io;
      if (!writeFileAtomically(args.table, accuracy::sweepTable(*axis, *report), io)) {
        printDiagnostics(io, global);
        return kExitUsageOrIo;
      }
    }
    if (args.json) {
      nlohmann::json j = accuracy::probeJson(*report);
      j["sweep"] = {{"axis", args.sweep}, {"max_abs_error", maxError}, {"worst_error_to_bound", worst}, {"worst_at", worstAt}};
      std::cout << j.dump(2) << "\n";
    }
    std::cerr << "sweep " << args.sweep << " of " << report->output << " on " << report->target << ": "
              << report->cases.size() << " points, " << report->failures() << " over the bound; max error " << maxError
              << ", worst error/bound " << worst << " at " << worstAt << "\n";
    return report->passed() ? kExitOk : kExitGraphError;
  } catch (const rt::RuntimeError& e) {
    std::cerr << "watergraph: probe: " << e.what() << "\n";
    return e.exitCode();
  } catch (const std::invalid_argument& e) {
    std::cerr << "watergraph: --mutate: " << e.what() << "\n";
    return kExitUsageOrIo;
  }
}

// --node TYPE: the cases that apply to the node (a port they set, a builtin it reads), each
// output, grouped by the options the cases give it; the suite's code path.
int runNodeProbe(const ProbeArgs& args, const GlobalOptions& global, const accuracy::ShaderMutation& mutation) {
  const NodeSpec* spec = defaultRegistry().find(args.node);
  if (!spec) {
    std::cerr << "watergraph: --node: no node type '" << args.node << "' (see watergraph nodes)\n";
    return kExitUsageOrIo;
  }
  if (!args.sweep.empty()) return runSweep(args, global, *spec, mutation);
  if (!args.options.empty()) {  // the cases give the options they probe ("options" in each case)
    std::cerr << "watergraph: --options applies to --sweep; with --cases, give each case its \"options\"\n";
    return kExitUsageOrIo;
  }
  if (args.cases.empty()) {
    std::cerr << "watergraph: probe --node needs --cases (or --sweep)\n";
    return kExitUsageOrIo;
  }
  Diagnostics diags;
  auto cases = accuracy::loadProbeCases(args.cases, diags);
  printDiagnostics(diags, global);
  if (!cases) return exitCodeFor(diags);
  try {
    auto executor = probeExecutor(args);
    accuracy::SuiteOptions options;
    options.nodes = {spec->type};
    options.variants = args.variants;
    options.mutation = mutation;
    accuracy::SuiteResult r = accuracy::runHardCaseSuite(*cases, *executor, options);
    executor->finish();
    nlohmann::json all = nlohmann::json::array();
    for (const auto& run : r.runs) {
      if (args.json) {
        nlohmann::json j = accuracy::probeJson(run.report);
        j["variant"] = run.variant;
        j["options"] = run.options;
        all.push_back(j);
      } else {
        std::cout << "[" << run.variant << "] " << run.options.dump() << "\n" << accuracy::formatProbeText(run.report);
      }
    }
    if (args.json) std::cout << all.dump(2) << "\n";
    for (const auto& e : r.errors) std::cerr << "watergraph: probe: " << e << "\n";
    std::cerr << r.caseRuns << " case runs, " << r.failures << " failed (" << r.nanInf << " NaN/Inf)\n";
    if (mutation.active() && r.mutatedRuns == 0) {
      std::cerr << "watergraph: --mutate: '" << mutation.find << "' is in none of " << spec->type << "'s probe shaders\n";
      return kExitUsageOrIo;
    }
    return r.failures || !r.errors.empty() ? kExitGraphError : kExitOk;
  } catch (const rt::RuntimeError& e) {
    std::cerr << "watergraph: probe: " << e.what() << "\n";
    return e.exitCode();
  }
}

// GRAPH --functions: every glsl_function node the graph resolves to (in its subgraphs too)
// swept over the value classes of the cases file's inputs (accuracy/function_sweep.h).
int runFunctionSweep(const ProbeArgs& args, const GlobalOptions& global) {
  Diagnostics diags;
  auto graph = loadGraphFile(args.graph, diags);
  auto cases = accuracy::loadProbeCases(args.cases, diags);
  if (graph && !args.preset.empty() && !applyPreset(*graph, args.preset, diags)) graph.reset();
  std::optional<std::vector<accuracy::FunctionNodeUnderTest>> nodes;
  if (graph && cases) nodes = accuracy::functionNodesOf(*graph, diags);
  printDiagnostics(diags, global);
  if (!nodes) return exitCodeFor(diags);
  if (nodes->empty()) {
    std::cerr << args.graph << ": no glsl_function node to sweep\n";
    return kExitOk;
  }
  try {
    auto executor = probeExecutor(args);
    accuracy::FunctionSweepResult r = accuracy::sweepFunctionNodes(*nodes, *cases, *executor);
    executor->finish();
    if (args.json) {
      nlohmann::json all = nlohmann::json::array();
      for (const auto& c : r.cases) {
        nlohmann::json gpu = nlohmann::json::array();
        for (int i = 0; i < c.components; ++i) {
          double g = c.gpu[static_cast<size_t>(i)];
          gpu.push_back(std::isfinite(g) ? nlohmann::json(g) : nlohmann::json(std::isnan(g) ? "nan" : g > 0 ? "inf" : "-inf"));
        }
        all.push_back({{"node", c.node}, {"output", c.output}, {"port", c.port}, {"case", c.inputClass},
                       {"gpu", gpu}, {"compared", c.compared}, {"passed", c.failure.empty()}});
        if (c.compared) all.back()["abs_error"] = c.absError, all.back()["bound"] = c.bound;
        if (!c.failure.empty()) all.back()["failure"] = c.failure;
      }
      std::cout << all.dump(2) << "\n";
    }
    std::cerr << accuracy::formatFunctionSweep(r);
    return r.failures || !r.errors.empty() ? kExitGraphError : kExitOk;
  } catch (const rt::RuntimeError& e) {
    std::cerr << args.graph << ": error: " << e.what() << "\n";
    return e.exitCode();
  }
}

int runProbe(const ProbeArgs& args, const GlobalOptions& global) {
  if (args.node.empty() == args.graph.empty()) {
    std::cerr << "watergraph: probe needs a GRAPH or --node TYPE (one of them)\n";
    return kExitUsageOrIo;
  }
  accuracy::ShaderMutation mutation;
  if (!args.mutate.empty()) {
    auto m = parseMutation(args.mutate);
    if (!m) {
      std::cerr << "watergraph: --mutate must be FIND=>REPLACE (got '" << args.mutate << "')\n";
      return kExitUsageOrIo;
    }
    mutation = *m;
  }
  if (args.functions && args.target == kWgslTargetName) {
    std::cerr << "watergraph: --functions sweeps glsl_function nodes, which are GLSL only: give a GLSL --target\n";
    return kExitUsageOrIo;
  }
  if (args.functions && !args.node.empty()) {
    std::cerr << "watergraph: --functions needs a GRAPH (it sweeps the graph's glsl_function nodes)\n";
    return kExitUsageOrIo;
  }
  if (!args.sweep.empty() && args.node.empty()) {
    std::cerr << "watergraph: --sweep needs --node TYPE\n";
    return kExitUsageOrIo;
  }
  if (args.vulkanValidation && args.target != "vk450") {
    std::cerr << "watergraph: --vk-validation needs --target vk450 (the layer checks Vulkan calls)\n";
    return kExitUsageOrIo;
  }
  if (!args.preset.empty() && !args.node.empty()) {
    std::cerr << "watergraph: --preset needs a GRAPH (a node probed alone has no presets; give it --options)\n";
    return kExitUsageOrIo;
  }
  if (!args.node.empty()) return runNodeProbe(args, global, mutation);
  if (args.functions) {
    if (args.cases.empty() || !args.output.empty() || mutation.active()) {
      std::cerr << "watergraph: probe GRAPH --functions needs --cases FILE (its inputs' values are the classes swept) "
                   "and takes no --output or --mutate\n";
      return kExitUsageOrIo;
    }
    return runFunctionSweep(args, global);
  }
  if (args.cases.empty()) {
    std::cerr << "watergraph: probe GRAPH needs --cases FILE\n";
    return kExitUsageOrIo;
  }
  ProbeOutput output;
  if (!args.output.empty()) {
    auto o = parseProbeOutput(args.output);
    if (!o) {
      std::cerr << "watergraph: --output must be NODE or NODE.PORT (got '" << args.output << "')\n";
      return kExitUsageOrIo;
    }
    output = *o;
  }
  Diagnostics diags;
  auto graph = loadGraphFile(args.graph, diags);
  auto cases = accuracy::loadProbeCases(args.cases, diags);
  if (graph && !args.preset.empty() && !applyPreset(*graph, args.preset, diags)) graph.reset();
  if (!graph || !cases) {
    printDiagnostics(diags, global);
    return exitCodeFor(diags);
  }
  try {
    auto executor = probeExecutor(args);
    auto report = accuracy::probeGraph(*graph, output, *cases, *executor, diags, mutation);
    executor->finish();
    printDiagnostics(diags, global);
    if (!report) return exitCodeFor(diags);
    if (args.json) std::cout << accuracy::probeJson(*report).dump(2) << "\n";
    else std::cout << accuracy::formatProbeText(*report);
    return report->passed() ? kExitOk : kExitGraphError;
  } catch (const rt::RuntimeError& e) {
    std::cerr << args.graph << ": error: " << e.what() << "\n";
    return e.exitCode();
  } catch (const std::invalid_argument& e) {
    std::cerr << "watergraph: --mutate: " << e.what() << "\n";
    return kExitUsageOrIo;
  }
}
#endif

}  // namespace

Runner addProbeCommand(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<ProbeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "probe",
      "Evaluate one output of a graph per case on the GPU in float32 (headless: GL for glsl330 and es300, Vulkan for "
      "vk450, WebGPU in headless Chromium for wgsl; one pixel of an RGBA32F target per case) and with the double reference; print GPU value, reference, absolute and relative error and NaN/Inf flags. "
      "A case sets the builtins (uv, world_position, normal, view_direction, time, camera, screen_uv, frag_depth, "
      "near_far), the scene textures' values and parameters; see docs/accuracy.md.\n\nExamples:\n"
      "  watergraph probe graphs/lake.json --cases tests/hardcases/lake.json\n"
      "  watergraph probe graphs/lake.json --output fresnel.reflectance --cases cases.json --target es300 --json\n"
      "  watergraph probe --node fresnel --cases tests/hardcases/suite.json --variants\n"
      "  watergraph probe graphs/caustic_pool.json --functions --cases tests/hardcases/suite.json\n"
      "  watergraph probe --node fresnel --cases tests/hardcases/suite.json --target vk450 --vk-validation\n"
      "  watergraph probe --node fresnel --cases tests/hardcases/suite.json --target wgsl\n"
      "  watergraph probe --node fresnel --options '{\"model\": \"exact\", \"direction\": \"water_to_air\"}' "
      "--sweep angle:0:90:10000 --table fresnel.dat\n"
      "  watergraph probe --node fresnel --cases c.json --mutate '1.333=>1.3331'\n\n"
      "Exit codes: 0 every case finite and within tolerance; 1 a NaN/Inf, a range or tolerance failure, or graph/case "
      "errors, a shader the driver rejects or a validation message; 2 usage, I/O, or no EGL/GL context or Vulkan device "
      "(wgsl: no Node.js, npm packages, Chromium or WebGPU adapter: the probe did not run).");
  cmd->add_option("graph", args->graph, "graph file (.json); or --node");
  cmd->add_option("--output", args->output, "the node output to probe, NODE.PORT (default: the fragment colour)");
  cmd->add_option("--preset", args->preset,
                  "graph mode: a preset from the graph's \"presets\" table: its parameter values and node options apply");
  cmd->add_option("--cases", args->cases, "cases file (.json), see docs/accuracy.md (with --sweep: its first case is the base)");
  cmd->add_option("--target", args->target,
                  "glsl330 (OpenGL 4.5 core), es300 (OpenGL ES 3.2), vk450 (its SPIR-V on Vulkan 1.3) or wgsl (the "
                  "WGSL module in headless Chromium's WebGPU, through Node.js and clients/webgpu's npm packages)")
      ->check(CLI::IsMember({"glsl330", "es300", "vk450", "wgsl"}))
      ->capture_default_str();
  cmd->add_flag("--vk-validation", args->vulkanValidation,
                "vk450: run under the Khronos validation layer; any message it reports fails the probe (exit 1)");
  cmd->add_flag("--json", args->json, "print the results as JSON on stdout");
  cmd->add_option("--node", args->node,
                  "probe a node type alone, every output, with the cases that apply to it (they may set \"inputs\", "
                  "\"options\" and \"ranges\"), as the hard-case suite does");
  cmd->add_flag("--functions", args->functions,
                "with a GRAPH: sweep its glsl_function nodes (in its subgraphs too): each input port over every value "
                "the --cases file gives an input of its type (a float also splatted), the others at 0.5, every output "
                "checked for NaN/Inf, and against the node's reference formula where it has one; a sampler2D "
                "parameter is held at a built-in texture (the node's, else its default)");
  cmd->add_flag("--variants", args->variants, "with --node: also every variant of its options");
  cmd->add_option("--sweep", args->sweep,
                  "with --node: NAME[.x|.y|.z|.w]:FROM:TO:COUNT, one input stepped evenly: 'angle' (degrees between "
                  "normal and view), an input port, or a builtin key of the cases file (time, world_position.x, ...)");
  cmd->add_option("--options", args->options, "with --sweep: the node's options as a JSON object (an expression's formula and inputs: its "
                  "inputs can then be swept); with --cases each case gives its own \"options\"");
  addOutputOption(cmd, "--table", args->table,
                  "with --sweep: write 'x gpu reference abs_error bound' per point to this file (for plotting)");
  cmd->add_option("--mutate", args->mutate,
                  "FIND=>REPLACE: edit the probe shader first (mutation testing: the probe should then fail); FIND "
                  "must occur in it");
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
