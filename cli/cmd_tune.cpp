// tune: the cheapest configuration of a graph's quality knobs whose every frame of a sweep
// of views and times stays within an error budget against the reference (every knob at its
// most exact level). A greedy descent (accuracy/tune_search.h) over measurements on the GL
// runtime (accuracy/tune_render.h); prints the path, optionally writes the result into the
// graph as a preset and plots every tried configuration.
#include <chrono>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

#include <unistd.h>

#include "core/frame_size_text.h"
#include "cli/commands.h"
#include "cli/option_values.h"
#include "cli/finite_number.h"
#include "cli/option_values.h"
#include "codegen/output_files.h"
#include "core/graph_io.h"
#include "core/node_spec.h"

#ifdef WG_HAVE_RUNTIME
#include "accuracy/tune_render.h"
#include "accuracy/tune_report.h"
#include "runtime/runtime_error.h"
#include "runtime/scene.h"
#endif

namespace wg::cli {
namespace {

constexpr size_t kMaxTuneTimes = 64;

struct TuneArgs {
  std::string graph;
  double minPsnr = NAN, maxAbsError = NAN;
  std::string cameras, times = "1,3.5,20", size = "160x90", target = "glsl330";
  int runs = 9;
  std::string writePreset, plot;
  std::string keep;        // nodes tune may not switch off, comma separated
  bool keepGiven = false;  // --keep was given (an empty list is a usage error, not "none")
  bool noBypass = false;   // switch no node off
};

#ifdef WG_HAVE_RUNTIME
int usage(const std::string& message) {
  std::cerr << "watergraph: tune: " << message << "\n";
  return kExitUsageOrIo;
}

std::string fixed(double x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}

int runTune(const TuneArgs& args) {
  using namespace accuracy;
  TuneBudget budget;
  if (!std::isnan(args.minPsnr)) budget.minPsnr = args.minPsnr;
  if (!std::isnan(args.maxAbsError)) budget.maxAbsError = args.maxAbsError;
  if (!budget.minPsnr && !budget.maxAbsError) return usage("give a budget: --min-psnr DB and/or --max-abs-error E");
  if (budget.maxAbsError && !(*budget.maxAbsError >= 0)) return usage("--max-abs-error must be >= 0");
  TuneSweep sweep;
  const auto size = parseFrameSizeText(args.size, 8, 9999);
  if (!size)
    return usage("--size must be WIDTHxHEIGHT, each side 8..9999 (got '" + args.size + "')");
  sweep.width = size->width;
  sweep.height = size->height;
  sweep.runs = args.runs;
  sweep.target = *parseTarget(args.target);
  std::string why;
  if (!args.cameras.empty()) {
    auto cameras = splitList("--cameras", args.cameras, &why);
    if (!cameras) return usage(why);
    for (const auto& c : *cameras) {
      if (!rt::cameraPreset(c)) {
        std::string names;
        for (const auto& n : rt::cameraPresetNames()) names += (names.empty() ? "" : ", ") + n;
        return usage("unknown camera '" + c + "' in --cameras (the cameras: " + names + ")");
      }
      sweep.cameras.push_back(c);
    }
  }
  sweep.times.clear();
  // Decimal numbers only: strtod alone also took " 1" and hexadecimal "0x10". (Checked by
  // characters, not std::regex, which recurses per character of a long argument.)
  auto decimal = [](const std::string& t) {
    return !t.empty() && t.size() <= 64 &&
           t.find_first_not_of("0123456789.eE+-") == std::string::npos && std::isdigit(static_cast<unsigned char>(t.back()));
  };
  auto times = splitList("--times", args.times, &why);
  if (!times) return usage(why);
  for (const auto& t : *times) {
    char* end = nullptr;
    double v = decimal(t) ? std::strtod(t.c_str(), &end) : NAN;
    if (end && *end != '\0') v = NAN;
    if (!fitsFiniteFloat(v))  // u_time is a float
      return usage("--times must be finite decimal numbers within float range, separated by commas (got '" + t + "')");
    sweep.times.push_back(v);
  }
  if (sweep.times.empty()) return usage("--times needs at least one time");
  // Every time is rendered from every camera for every configuration tried.
  if (sweep.times.size() > kMaxTuneTimes)
    return usage("--times gives " + std::to_string(sweep.times.size()) + " times; at most " + std::to_string(kMaxTuneTimes));
  if (!args.writePreset.empty() && !isIdentifier(args.writePreset))
    return usage("--write-preset '" + args.writePreset + "' is not an identifier (letters, digits, _; not starting with a digit)");

  // The graph is rewritten at the end with --write-preset: checked now, not after the search.
  if (!args.writePreset.empty()) {
    Diagnostics w;
    if (!checkWritable(realPathForRewrite(args.graph), w)) {
      for (const auto& d : w.all()) std::cerr << formatText(d) << "\n";
      return kExitUsageOrIo;
    }
  }
  Diagnostics diags;
  auto snapshot = readGraphFile(args.graph, diags);
  std::optional<Graph> graph;
  if (snapshot) graph = loadGraphFile(args.graph, diags);
  if (!graph) {
    for (const auto& d : diags.all()) std::cerr << formatText(d) << "\n";
    return exitCodeFor(diags);
  }
  std::vector<TuneKnob> declared = graphKnobs(*graph);
  const bool hadKnobs = !declared.empty();
  std::vector<std::string> keep;
  if (args.keepGiven) {
    auto entries = splitList("--keep", args.keep, &why);  // as every list (cli/option_values.h)
    if (!entries) return usage(why);
    keep = *entries;
  }
  std::vector<std::string> unknownKeep = dropBypassKnobs(declared, keep, args.noBypass);
  if (!unknownKeep.empty()) {
    std::string switchable;
    for (const auto& k : graphKnobs(*graph))
      if (k.option == kBypassOption) switchable += (switchable.empty() ? "" : ", ") + k.node;
    return usage("--keep names '" + unknownKeep.front() + "', which is not a node tune could switch off (" +
                 (switchable.empty() ? std::string("this graph has none") : "those are: " + switchable) + ")");
  }
  if (declared.empty() && hadKnobs) {
    std::cerr << args.graph << ": error: with --keep/--no-bypass the graph has no quality knob left to tune\n";
    return kExitGraphError;
  }
  if (declared.empty()) {
    std::cerr << args.graph << ": error: the graph has no quality knob to tune (options whose levels a node declares, "
              << "and `bypass` on nodes that add detail; `watergraph nodes` lists them)\n";
    return kExitGraphError;
  }
  // Levels that compile to the same shaders as the next more exact one stand for nothing
  // here: tuning them would time identical shaders against each other.
  std::vector<std::string> unchanged;
  std::vector<TuneKnob> knobs = distinctKnobLevels(*graph, declared, sweep.target, unchanged);
  std::string unchangedText;
  for (const auto& u : unchanged) unchangedText += (unchangedText.empty() ? "" : ", ") + u;
  if (knobs.empty()) {
    std::cerr << args.graph << ": error: no quality knob changes this graph's shaders (" << unchangedText
              << ": every level compiles to the same shaders here)\n";
    return kExitGraphError;
  }
  const bool terminal = ::isatty(STDERR_FILENO);
  auto started = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  };
  try {
    GlTuneMeasurements gl(*graph, knobs, sweep);
    int measured = 0;
    TuneProgress progress;
    if (terminal)
      progress = [&](const std::string& line) {
        std::cerr << "tune [" << fixed(elapsed(), 0) << " s, " << ++measured << "] " << line << "\n";
      };
    std::string cameras;
    for (const auto& c : gl.sweep().cameras) cameras += (cameras.empty() ? "" : ", ") + c;
    std::string times;
    for (double t : gl.sweep().times) times += (times.empty() ? "" : ", ") + fixed(t, 1);
    std::cout << "tune " << args.graph << ": " << budget.text() << "; " << gl.viewLabels().size() << " frames ("
              << cameras << " at t = " << times << " s), " << sweep.width << "x" << sweep.height << " RGBA32F, "
              << args.target << " on " << gl.renderer() << "; " << knobs.size() << (knobs.size() == 1 ? " knob" : " knobs")
              << (unchanged.empty() ? "" : " (not tuned, no level changes the shaders here: " + unchangedText + ")")
              << "\n\n";
    TuneResult result = tuneSearch(knobs, budget, gl, progress);
    std::cout << tunePathTable(result)
              << "(each step's ms/MP as timed in the round that took it; the configurations below are timed together)\n\n"
              << tuneStopText(result) << "\n";
    if (!args.plot.empty()) {
      Diagnostics w;
      if (!writeFileAtomically(args.plot, tunePlotSvg(result, budget, "watergraph tune " + args.graph + ": " + budget.text()), w)) {
        for (const auto& d : w.all()) std::cerr << formatText(d) << "\n";
        return kExitUsageOrIo;
      }
      std::cerr << "wrote " << args.plot << "\n";
    }
    if (!result.found) {
      std::cerr << args.graph << ": error: " << result.why << " (" << budget.text() << ")\n";
      return kExitGraphError;
    }
    const TuneStep& chosen = result.chosen();
    TuneError asWritten = gl.asWrittenError();
    std::vector<TuneCost> final = gl.costOf({result.path.front().config, std::nullopt, chosen.config});
    // Switching a node off drops an art feature: said first, with how to forbid it.
    std::vector<std::string> off = bypassedNodes(knobs, chosen.config);
    if (!off.empty()) {
      std::string names;
      for (const auto& n : off) names += (names.empty() ? "" : ",") + n;
      std::cout << "switched off: " << names << " (what " << (off.size() == 1 ? "it draws" : "they draw")
                << " is gone from the chosen configuration; forbid it with --keep " << names << ", or --no-bypass)\n";
    }
    std::cout << "chosen: " << configText(knobs, chosen.config) << "\n";
    std::cout << "verified (rendered again): worst PSNR "
              << (std::isinf(result.verified.worstPsnr) ? "inf" : fixed(result.verified.worstPsnr, 1)) << " dB"
              << (std::isinf(result.verified.worstPsnr) ? "" : " (" + result.verified.worstFrame + ")") << ", max abs error "
              << result.verified.maxAbsError << "\n";
    std::cout << "cost, timed together (" << sweep.runs << " interleaved repeats): reference " << fixed(final[0].msPerMegapixel, 1)
              << " ms/MP (" << final[0].spirvInstructions << " SPIR-V instr.), as written " << fixed(final[1].msPerMegapixel, 1)
              << " ms/MP (" << final[1].spirvInstructions << "; worst PSNR "
              << (asWritten.finite ? (std::isinf(asWritten.worstPsnr) ? std::string("inf") : fixed(asWritten.worstPsnr, 1)) : "NaN/Inf")
              << " dB), chosen " << fixed(final[2].msPerMegapixel, 1) << " ms/MP (" << final[2].spirvInstructions << ")\n";
    std::cout << "speed-up: " << fixed(final[0].msPerMegapixel / final[2].msPerMegapixel, 2) << "x against the reference, "
              << fixed(final[1].msPerMegapixel / final[2].msPerMegapixel, 2) << "x against the graph as written\n";
    std::cout << result.tried.size() << " configurations tried in " << fixed(elapsed(), 1) << " s\n";
    if (!args.writePreset.empty()) {
      Diagnostics w;
      auto text = graphWithPreset(*snapshot, args.graph, args.writePreset, knobs, chosen.config, w);
      // The file changed while tuning (an editor saved it): writing the old snapshot would lose that edit.
      auto now = readGraphFile(args.graph, w);
      if (text && now && *now != *snapshot)
        w.error(DiagCode::FileWrite, SourceRef{args.graph, 0, 0}, "the file changed while it was being tuned; preset not written");
      if (!text || w.hasErrors() || !writeFileAtomically(realPathForRewrite(args.graph), *text, w)) {
        for (const auto& d : w.all()) std::cerr << formatText(d) << "\n";
        return exitCodeFor(w);
      }
      std::cout << "wrote preset '" << args.writePreset << "' into " << args.graph << "\n";
    }
  } catch (const rt::RuntimeError& e) {
    std::cerr << "watergraph: tune: " << e.what() << "\n";
    return e.exitCode();
  } catch (const std::runtime_error& e) {
    std::cerr << args.graph << ": error: " << e.what() << "\n";
    return kExitGraphError;
  }
  return kExitOk;
}
#endif

}  // namespace

Runner addTuneCommand(CLI::App& app, const GlobalOptions&) {
  auto args = std::make_shared<TuneArgs>();
  CLI::App* cmd = app.add_subcommand(
      "tune",
      "The cheapest configuration of a graph's quality knobs within an error budget. The reference is the graph with "
      "every knob (options whose levels a node declares, and `bypass` on nodes that add detail; `watergraph nodes` "
      "lists them; those of nodes inside a subgraph instance are named instance/node.option; levels that compile to "
      "the same shaders as the next more exact one are left out) at its most exact level, rendered into RGBA32F "
      "frames over a sweep: every camera (default above, "
      "grazing, topdown, and underwater for graphs with the deferred underwater pass) at every time. From the reference, "
      "a greedy descent tries lowering each knob one level; a candidate qualifies when every frame meets the budget "
      "(PSNR over RGB with peak 1, max abs error; NaN or Inf anywhere rejects it) and it saves cost (faster than the "
      "current configuration in enough of the paired, interleaved repeats that chance is unlikely: a one-sided sign "
      "test at 10 %; or fewer SPIR-V instructions and not slower by that test); the one with the "
      "least error increase per ms/MP saved is taken (ties: fewer SPIR-V instructions, then the knob's name), until "
      "none qualifies. Cost: CPU ms per megapixel (the process's CPU time across each frame, llvmpipe's threads included, "
      "so other programs on the machine do not inflate it), the median of interleaved repeats of every camera at the first time, timed "
      "beside the current configuration; SPIR-V instructions after spirv-opt -O. The chosen configuration is rendered "
      "again and checked once more. Prints the path, then the chosen configuration timed beside the reference and the "
      "graph as written.\n\n"
      "Examples:\n  watergraph tune graphs/lake.json --min-psnr 45\n"
      "  watergraph tune graphs/pool.json --min-psnr 45 --cameras above,grazing --times 0,5,30 --write-preset fast\n"
      "  watergraph tune graphs/ocean.json --max-abs-error 0.02 --plot tune.svg\n"
      "  watergraph tune graphs/river.json --min-psnr 40 --keep foam   # never switch the shore foam off\n\n"
      "Exit codes: 0 a configuration found; 1 the graph has no knob, does not load or compile, or no configuration "
      "cheaper than the reference meets the budget; 2 usage, I/O, or no EGL/GL.");
  cmd->add_option("graph", args->graph, "the graph file (.json)")->required();
  cmd->add_option("--min-psnr", args->minPsnr, "budget: every frame's PSNR (dB, peak 1) at least this")->check(finiteFloat());
  cmd->add_option("--max-abs-error", args->maxAbsError, "budget: no colour channel of any pixel off by more than this")
      ->check(finiteFloat());
  cmd->add_option("--cameras", args->cameras, "camera presets, comma separated (above, grazing, underwater, topdown)");
  cmd->add_option("--times", args->times, "scene times in seconds, comma separated")->capture_default_str();
  cmd->add_option("--size", args->size, "WIDTHxHEIGHT of the frames")->capture_default_str();
  cmd->add_option("--runs", args->runs, "interleaved timed repeats per round (a time saving counts when a one-sided sign test over them passes at 10 %: 7 of 9, all of 5; under 4 none can, and the search goes by SPIR-V instructions)")->check(CLI::Range(1, 1000))->capture_default_str();
  cmd->add_option("--target", args->target, "glsl330 or es300")->check(CLI::IsMember({"glsl330", "es300"}))->capture_default_str();
  cmd->add_option("--write-preset", args->writePreset,
                  "write the chosen configuration into the graph as this preset (canonical form; replaces one of that name)")
      // Checked when given, so an empty name is refused too (not taken as "not given").
      ->check([](const std::string& name) {
        return isIdentifier(name) ? std::string()
                                  : "'" + name + "' is not an identifier (letters, digits, _; not starting with a digit)";
      });
  cmd->add_option("--keep", args->keep,
                  "never switch off these nodes (their `bypass` knob), comma separated qualified ids as the result "
                  "names them (edges,foam/edge)")
      ->each([args](const std::string&) { args->keepGiven = true; });
  cmd->add_flag("--no-bypass", args->noBypass, "never switch off any node: tune only the knobs that keep every node drawn");
  addOutputOption(cmd, "--plot", args->plot, "draw every tried configuration, cost against worst PSNR, into this SVG");
#ifdef WG_HAVE_RUNTIME
  return [args] { return runTune(*args); };
#else
  return [] {
    std::cerr << "watergraph: tune: this build has no GL runtime (configure with -DWG_BUILD_RUNTIME=ON)\n";
    return kExitUsageOrIo;
  };
#endif
}

}  // namespace wg::cli
