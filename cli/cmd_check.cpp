// check: render graphs into a float frame over a sweep of cameras (grazing to top-down,
// under water where the graph has the deferred pass), times up to 1e6 s and sun
// positions; count NaN/Inf pixels and compare sampled pixels with the CPU reference on
// the inputs read back from the GPU, each held to the graph's error bound; --error-map writes the
// per-pixel errors of the worst view. Exit 1 on any NaN or Inf or a pixel over its bound.
#include <filesystem>
#include <map>
#include <iostream>
#include <memory>

#include "core/frame_size_text.h"
#include "cli/commands.h"
#include "cli/option_values.h"
#include "cli/view_flags.h"
#include "cli/wgsl_checks.h"
#include "cli/wgsl_executor.h"
#include "codegen/emit_wgsl.h"

#ifdef WG_HAVE_RUNTIME
#include "accuracy/check.h"
#include "accuracy/error_bound.h"
#include "accuracy/target_agreement.h"
#include "accuracy/gpu_executor.h"
#include "codegen/compile.h"
#include "codegen/output_files.h"
#include "codegen/texture_files.h"
#include "core/graph_io.h"
#include "core/node_preview_graph.h"
#include "nodes/registry.h"
#include "runtime/image.h"
#include "runtime/pass_plan.h"
#include "runtime/preview.h"
#include "runtime/runtime_error.h"
#endif

namespace wg::cli {
namespace {

struct CheckArgs {
  std::vector<std::string> graphs;
  std::string target = "all";
  std::string size = "160x90";
  std::string errorMap;  // FILE.png: the error image (several graphs: FILE-GRAPH.png)
  std::string mutate;    // FIND=>REPLACE in the water shaders
  std::string preset;    // a preset of each graph, applied before compiling
  bool vulkanValidation = false;  // vk450: under the Khronos validation layer
  ViewFlags view;                 // the error map's picture of the frame
};

#ifdef WG_HAVE_RUNTIME
// The error map of one graph on one target: FILE.png, with -GRAPH for several graphs and
// -TARGET for several targets (--target all), so none replaces another.
std::string errorMapFile(const std::string& given, const std::string& graphPath, const std::string& target, bool severalGraphs,
                         bool severalTargets) {
  std::filesystem::path f(given);
  std::string stem = f.stem().string();
  if (severalGraphs) stem += "-" + std::filesystem::path(graphPath).stem().string();
  if (severalTargets) stem += "-" + target;
  f.replace_filename(stem + f.extension().string());
  return f.string();
}

// The WebGPU executor (clients/webgpu/executor_server.mjs: Node.js and headless Chromium).
// Throws rt::RuntimeError (Kind::Environment: exit 2) naming what is missing: check did not
// run on wgsl, and never passes.
std::unique_ptr<accuracy::GpuExecutor> wgslCheckExecutor() {
  // playwright-core starts Chromium; naga-wasm translates the runtime's scene shaders.
  return wgslExecutorOrWhyNot("check did not run on wgsl: ", {"playwright-core", "naga-wasm"});
}

int runCheck(const CheckArgs& args, const GlobalOptions& global) {
  const auto size = parseFrameSizeText(args.size, 8, 4096);
  if (!size) {
    std::cerr << "watergraph: --size must be WIDTHxHEIGHT with each side 8..4096, e.g. 160x90 (got '" << args.size << "')\n";
    return kExitUsageOrIo;
  }
  accuracy::CheckOptions options;
  options.width = size->width;
  options.height = size->height;
  options.errorMaps = !args.errorMap.empty();
  if (!args.mutate.empty()) {
    auto at = args.mutate.find("=>");  // GLSL has '=' but no "=>"
    if (at == std::string::npos || at == 0) {
      std::cerr << "watergraph: --mutate must be FIND=>REPLACE (got '" << args.mutate << "')\n";
      return kExitUsageOrIo;
    }
    options.mutation = {args.mutate.substr(0, at), args.mutate.substr(at + 2)};
  }
  if (args.vulkanValidation && args.target != "vk450" && args.target != "all") {
    std::cerr << "watergraph: --vk-validation needs --target vk450 or all (the layer checks Vulkan calls)\n";
    return kExitUsageOrIo;
  }
  // The targets by the names the reports use: wgsl's module shares es300's plan (its executor's
  // target is es300; the compile adds GRAPH.wgsl).
  std::vector<std::string> targets;
  if (args.target == "all") targets = {"glsl330", "es300", "vk450"};
  else targets = {args.target};
  // One error map per graph and target: two graphs of one file name would write the same
  // FILE-GRAPH.png, the second replacing the first; refused before anything is rendered.
  if (!args.errorMap.empty() && args.graphs.size() > 1) {
    std::map<std::string, std::string> byStem;
    for (const auto& path : args.graphs) {
      auto [it, fresh] = byStem.emplace(std::filesystem::path(path).stem().string(), path);
      if (fresh || it->second == path) continue;
      std::cerr << "watergraph: '" << it->second << "' and '" << path << "' would both write the error map "
                << errorMapFile(args.errorMap, path, targets.front(), true, targets.size() > 1)
                << "; check them one at a time\n";
      return kExitUsageOrIo;
    }
  }
  // Each error map's own name (FILE-GRAPH-TARGET.png) is checked before anything is
  // rendered, as FILE.png was (cli/option_values.h).
  if (!args.errorMap.empty()) {
    Diagnostics out;
    for (const std::string& target : targets)
      for (const auto& path : args.graphs)
        checkWritable(errorMapFile(args.errorMap, path, target, args.graphs.size() > 1, targets.size() > 1), out);
    if (out.hasErrors()) {
      printDiagnostics(out, global);
      return kExitUsageOrIo;
    }
  }
  int exit = kExitOk;
  // Graphs with a node that has no double reference: their reports on each target, frames
  // kept, held to each other once every target has rendered them.
  struct WithoutReference {
    std::string node;
    double tolerance = 0;
    std::vector<accuracy::CheckReport> reports;
  };
  std::map<std::string, WithoutReference> withoutReference;
  for (const std::string& targetLabel : targets) {
    const bool wgsl = targetLabel == kWgslTargetName;
    const Target target = wgsl ? Target::Es300 : *parseTarget(targetLabel);
    std::unique_ptr<accuracy::GpuExecutor> executor;
    try {
      if (wgsl) {
        executor = wgslCheckExecutor();
      } else {
        accuracy::ExecutorOptions executorOptions;
        executorOptions.vulkanValidation = args.vulkanValidation && target == Target::Vk450;
        executorOptions.tessellation = true;  // a graph may tessellate its water
        executor = accuracy::makeGpuExecutor(target, executorOptions);
      }
    } catch (const rt::RuntimeError& e) {
      std::cerr << "watergraph: check: " << e.what() << "\n";
      return e.exitCode();
    }
    for (const auto& path : args.graphs) {
      Diagnostics diags;
      auto graph = loadGraphFile(path, diags);
      // A function graph with no output slots shows its first interface output, as in the editor.
      if (std::string why; graph && graph->interface && graph->outputs.empty())
        if (auto shown = interfaceOutputGraph(*graph, &why)) graph = std::move(shown);
      std::optional<CompileResult> result;
      if (graph) {
        CompileOptions options;
        options.targets = {target};
        options.wgsl = wgsl;
        options.preset = args.preset;
            result = compileGraph(*graph, defaultRegistry(), options, diags);
      }
      printDiagnostics(diags, global);
      if (!result) {
        exit = std::max(exit, exitCodeFor(diags));
        continue;
      }
      try {
        accuracy::CheckOptions graphOptions = options;
        std::string unreferenced = accuracy::nodeWithoutReference(result->program);
        graphOptions.keepFrames = !unreferenced.empty();
        auto report = accuracy::checkGraph(*result, path, *executor, graphOptions);
        std::cout << accuracy::formatCheckText(report);
        if (report.failed()) exit = std::max(exit, kExitGraphError);
        rt::Image map = accuracy::errorMapImage(report, args.view.over(result->program.view));
        if (map.width > 0) {
          std::string file = errorMapFile(args.errorMap, path, targetLabel, args.graphs.size() > 1, targets.size() > 1);
          rt::writePng(file, map);
          std::cout << "  error map: " << file << "\n";
        } else if (options.errorMaps) {
          std::cout << "  error map: none (nothing compared; reference: " << report.reference << ")\n";
        }
        if (!unreferenced.empty()) {
          WithoutReference& kept = withoutReference[path];
          kept.node = unreferenced;
          kept.tolerance = accuracy::programErrorModel(result->program).tolerance;
          kept.reports.push_back(std::move(report));
        }
      } catch (const rt::TextureLoadError& e) {
        Diagnostics textureDiags;
        reportUnusableTexture(result->program, &*graph, e.source(), e.why(), textureDiags);
        printDiagnostics(textureDiags, global);
        exit = std::max(exit, kExitGraphError);
      } catch (const rt::RuntimeError& e) {
        std::cerr << path << ": error: " << e.what() << "\n";
        exit = std::max(exit, e.exitCode());
      } catch (const std::invalid_argument& e) {
        std::cerr << "watergraph: --mutate: " << e.what() << "\n";
        return kExitUsageOrIo;
      }
    }
    try {
      executor->finish();
    } catch (const rt::RuntimeError& e) {
      std::cerr << "watergraph: check: " << e.what() << "\n";
      exit = std::max(exit, e.exitCode());
    }
  }
  for (const auto& path : args.graphs) {
    auto it = withoutReference.find(path);
    if (it == withoutReference.end()) continue;
    const WithoutReference& kept = it->second;
    std::cout << "targets of " << path << " against each other (" << kept.node << " has no double reference):\n";
    if (kept.reports.size() < 2) {
      std::cout << "  only " << kept.reports.front().targetLabel
                << " was checked: --target all holds glsl330, es300 and vk450 to each other\n";
      continue;
    }
    bool failed = false;
    for (size_t k = 1; k < kept.reports.size(); ++k) {
      auto agreement = accuracy::compareTargets(kept.reports.front(), kept.reports[k], kept.tolerance);
      std::cout << accuracy::formatTargetAgreement(agreement);
      failed |= agreement.failed();
    }
    std::cout << (failed ? "FAIL" : "ok") << ": the targets " << (failed ? "disagree beyond" : "agree within")
              << " twice the graph's tolerance " << kept.tolerance << "\n";
    if (failed) exit = std::max(exit, kExitGraphError);
  }
  return exit;
}
#endif

}  // namespace

Runner addCheckCommand(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<CheckArgs>();
  CLI::App* cmd = app.add_subcommand(
      "check",
      "Render graphs headless into an RGBA32F frame over a sweep: camera elevation 0.5 to 89.5 degrees, under water "
      "(graphs with the underwater node), times 13107, 524288 and 1e6 s, sun near the horizon, overhead and below it. "
      "glsl330 and es300 run on headless GL, vk450 (the SPIR-V compile writes) on Vulkan, wgsl (GRAPH.wgsl) in headless "
      "Chromium's WebGPU through Node.js and clients/webgpu (the WebGPU runner's passes). "
      "Counts NaN and Inf pixels; on glsl330, vk450 and wgsl compares sampled water pixels with the CPU reference evaluated on the "
      "inputs the GPU's fragment shader had there (read back: varyings, depth, scene and texture look-ups), each held to the graph's error bound (the probe's: the largest tolerance of its ops plus the conditioning of "
      "the pixel's inputs), and reports max and mean error per view and per graph. Scene passes are rendered at the "
      "frame's size, also for a graph whose nodes' `resolution` reduces them (the output says so). See docs/accuracy.md.\n\n"
      "Examples:\n  watergraph check graphs/*.json\n"
      "  watergraph check graphs/lake.json --target glsl330 --size 320x180 --error-map lake-error.png\n"
      "  watergraph check graphs/*.json --target vk450 --vk-validation\n"
      "  watergraph check graphs/lake.json --target wgsl\n\n"
      "Exit codes: 0 no NaN/Inf and every compared pixel within its bound; 1 a NaN/Inf pixel, a pixel over its bound, "
      "graph errors, a shader the driver rejects or a validation message; 2 usage, I/O, or no EGL/GL context or Vulkan "
      "device (wgsl: no Node.js, npm packages, Chromium or WebGPU adapter: check did not run).");
  cmd->add_option("graphs", args->graphs, "graph files (.json)")->required();
  cmd->add_option("--target", args->target,
                  "glsl330, es300, vk450, all (the three), or wgsl (WebGPU in headless Chromium through Node.js; not in all)")
      ->check(CLI::IsMember({"glsl330", "es300", "vk450", "wgsl", "all"}))
      ->capture_default_str();
  cmd->add_flag("--vk-validation", args->vulkanValidation,
                "vk450: run under the Khronos validation layer; any message it reports fails the graph (exit 1)");
  cmd->add_option("--size", args->size,
                  "WIDTHxHEIGHT of the frame, each side 8..4096, and within the memory budget (2 GiB; a graph with "
                  "several scene passes reaches it below 4096x4096: the error says what the size needs)")
      ->capture_default_str();
  cmd->add_option("--preset", args->preset,
                  "a preset from each graph's \"presets\" table: its parameter values and node options apply");
  addViewFlags(cmd, args->view);
  addOutputOption(cmd, "--error-map", args->errorMap,
                  "write the per-pixel error against the CPU of the worst view as a PNG (the frame's size; every water "
                  "pixel compared): grey on a log scale from 1e-8 (black) to 1e-3 (white), red over the error bound, "
                  "not compared: the frame through --tonemap/--exposure, darkened and tinted blue. With several graphs, FILE-GRAPH.png per graph; with --target all, FILE-TARGET.png "
                  "per target (FILE-GRAPH-TARGET.png for both)");
  cmd->add_option("--mutate", args->mutate,
                  "FIND=>REPLACE: edit the water shaders before rendering (a wrong node: check must fail)");
#ifdef WG_HAVE_RUNTIME
  return [args, &global] { return runCheck(*args, global); };
#else
  return [] {
    std::cerr << "watergraph: check: this build has no GL runtime (configure with -DWG_BUILD_RUNTIME=ON)\n";
    return kExitUsageOrIo;
  };
#endif
}

}  // namespace wg::cli
