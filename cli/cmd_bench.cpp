// bench: speed against error. Renders every quality level of every family in
// bench/variants.json (Fresnel models, Voronoi cell search, wave count, bisection and SSR
// steps, normal blends, caustic layers, the underwater graph's presets), or of every
// quality knob of one graph (`bench GRAPH`), in interleaved runs beside a pass-through shader; prints a markdown table of ms per megapixel, ratio,
// SPIR-V size after spirv-opt and error against the reference level, and draws the plot.
#include <fstream>
#include <iostream>
#include <memory>

#include "core/frame_size_text.h"
#include "cli/commands.h"
#include "cli/option_values.h"
#include "codegen/output_files.h"

#ifdef WG_HAVE_RUNTIME
#include <nlohmann/json.hpp>

#include "accuracy/bench.h"
#include "runtime/runtime_error.h"
#include "runtime/scene.h"
#endif

namespace wg::cli {
namespace {

struct BenchArgs {
  std::string graph;  // `bench GRAPH`: the graph's own quality knobs
  std::string preset, camera = "above";
  std::string config = "bench/variants.json";
  std::string size = "320x320";
  int runs = 5;
  std::string target = "glsl330";
  std::vector<std::string> families;
  std::string markdown;
  std::string plot;
};

#ifdef WG_HAVE_RUNTIME
int runBenchCommand(const BenchArgs& args) {
  const auto size = parseFrameSizeText(args.size, 8, 9999);
  if (!size) {
    std::cerr << "watergraph: --size must be WIDTHxHEIGHT, each side 8..9999 (got '" << args.size << "')\n";
    return kExitUsageOrIo;
  }
  if (args.graph.empty() && !std::ifstream(args.config)) {
    std::cerr << args.config << ": error: [WG050] cannot read the bench configuration\n";
    return kExitUsageOrIo;
  }
  if (!args.graph.empty() && !std::ifstream(args.graph)) {
    std::cerr << args.graph << ": error: [WG050] cannot read the file\n";
    return kExitUsageOrIo;
  }
  if (!args.camera.empty() && !rt::cameraPreset(args.camera)) {
    std::cerr << "watergraph: bench: unknown --camera '" << args.camera << "'\n";
    return kExitUsageOrIo;
  }
  if (args.graph.empty() && !args.preset.empty()) {
    std::cerr << "watergraph: bench: --preset applies to a GRAPH (bench GRAPH --preset NAME)\n";
    return kExitUsageOrIo;
  }
  accuracy::BenchSettings s;
  s.configFile = args.config;
  s.graphFile = args.graph;
  s.preset = args.preset;
  s.camera = args.camera;
  s.width = size->width;
  s.height = size->height;
  s.runs = args.runs;
  s.target = *parseTarget(args.target);
  s.families = args.families;
  try {
    accuracy::BenchResult r = accuracy::runBench(s);
    std::string table = accuracy::benchMarkdown(r);
    std::cout << table;
    if (!args.markdown.empty()) {
      Diagnostics io;
      if (!writeFileAtomically(args.markdown, table, io)) {
        printDiagnostics(io, GlobalOptions{});
        return kExitUsageOrIo;
      }
    }
    if (!args.plot.empty()) {
      std::string why = accuracy::writeBenchPlot(r, args.plot);
      if (!why.empty()) {
        std::cerr << "watergraph: bench: cannot draw " << args.plot << ": " << why << "\n";
        return kExitUsageOrIo;
      }
      std::cerr << "wrote " << args.plot << "\n";
    }
  } catch (const rt::RuntimeError& e) {
    std::cerr << "watergraph: bench: " << e.what() << "\n";
    return e.exitCode();
  } catch (const accuracy::BenchUsageError& e) {
    std::cerr << e.what() << "\n";
    return kExitUsageOrIo;
  } catch (const std::runtime_error& e) {
    std::cerr << e.what() << "\n";
    return kExitGraphError;
  } catch (const nlohmann::json::exception& e) {
    // A level's settings of a shape the families' checks do not cover.
    std::cerr << (args.graph.empty() ? args.config : args.graph) << ": error: [WG004] a value has the wrong JSON type ("
              << e.what() << ")\n";
    return kExitGraphError;
  }
  return kExitOk;
}
#endif

}  // namespace

Runner addBenchCommand(CLI::App& app, const GlobalOptions& global) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* cmd = app.add_subcommand(
      "bench",
      "Speed against error: render every quality level of the families in bench/variants.json (Fresnel models, Voronoi "
      "cell search, wave count, bisection steps, SSR steps, normal blends, caustic layers, the underwater graph's "
      "fast/balanced/reference presets) in interleaved runs beside a pass-through shader. With a GRAPH, measure that "
      "graph's own quality knobs instead (options of the graph file's nodes whose levels the node declares, "
      "`watergraph nodes` lists them, "
      "and `bypass` on nodes that add detail): one family per knob, named node.option, with every other knob at its "
      "most exact level (the reference), and the graph as written against that reference. Prints a markdown table: ms "
      "per megapixel (median), ratio to the pass-through, SPIR-V instructions after spirv-opt -O, max/mean abs error and "
      "PSNR against the reference level; --plot draws cost against error with the Pareto front (gnuplot).\n\n"
      "Examples:\n  watergraph bench\n  watergraph bench graphs/stylized.json --camera grazing\n  watergraph bench --runs 9 --markdown bench.md --plot docs/images/speed-vs-error.png\n"
      "  watergraph bench --family 'SSR steps' --size 640x360\n\n"
      "Exit codes: 0 ok; 1 a family that does not load or compile; 2 usage, I/O, no gnuplot for --plot, or no EGL/GL.");
  cmd->add_option("graph", args->graph, "measure this graph's quality knobs instead of the configuration's families");
  cmd->add_option("--preset", args->preset, "with GRAPH: apply this preset of the graph first");
  cmd->add_option("--camera", args->camera, "with GRAPH: the camera preset every family is seen from")->capture_default_str();
  cmd->add_option("--config", args->config, "families and levels (.json)")->capture_default_str();
  cmd->add_option("--size", args->size, "WIDTHxHEIGHT of the frames")->capture_default_str();
  cmd->add_option("--runs", args->runs, "interleaved timed runs (after one warm-up frame each)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd->add_option("--target", args->target, "glsl330 or es300")->check(CLI::IsMember({"glsl330", "es300"}))->capture_default_str();
  cmd->add_option("--family", args->families, "run only this family (repeatable; with GRAPH: node.option or 'as written')");
  addOutputOption(cmd, "--markdown", args->markdown, "also write the table to this file");
  addOutputOption(cmd, "--plot", args->plot, "draw cost against error with the Pareto front into this PNG (needs gnuplot)");
#ifdef WG_HAVE_RUNTIME
  return [args] { return runBenchCommand(*args); };
#else
  return [] {
    std::cerr << "watergraph: bench: this build has no GL runtime (configure with -DWG_BUILD_RUNTIME=ON)\n";
    return kExitUsageOrIo;
  };
#endif
}

}  // namespace wg::cli
