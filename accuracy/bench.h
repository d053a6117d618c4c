#pragma once
// `watergraph bench`: speed against error. bench/variants.json lists families — a graph
// and its quality levels (option values per node id, or a node's quality knob, whose
// levels its spec declares) — e.g. Fresnel models, Voronoi cell search, wave count,
// bisection and SSR steps, normal blends, caustic layers, and the underwater graph's
// fast / balanced / reference presets. `bench GRAPH` measures every quality knob of one
// graph instead: a family per knob, the other knobs at their most exact level. Every level is rendered on the
// GL runtime into an RGBA32F frame, in interleaved runs (run 1: every level, run 2: every
// level, ...) together with a pass-through graph (the interpolated normal as colour), so
// the medians share the machine's state; cost is ms per megapixel and its ratio to the
// pass-through, plus the fragment shader's SPIR-V instruction count after spirv-opt -O;
// error is against the family's reference level: max and mean absolute error and PSNR
// (peak 1) over the frame.
#include <stdexcept>
#include <string>
#include <vector>

#include "codegen/target.h"

namespace wg::accuracy {

struct BenchSettings {
  std::string configFile = "bench/variants.json";
  // `bench GRAPH`: the graph's own quality knobs instead of the configuration's families,
  // with `preset` applied first and every family seen from `camera`.
  std::string graphFile, preset, camera = "above";
  std::string root = ".";  // graph_file entries are relative to it
  int width = 320, height = 320;
  int runs = 5;
  Target target = Target::Glsl330;
  std::vector<std::string> families;  // names to run; empty: all
};

struct BenchLevel {
  std::string family, level, node, camera;
  bool reference = false;
  double medianMs = 0, msPerMegapixel = 0, ratio = 0;  // ratio: to the pass-through, same run
  int spirvInstructions = -1;
  double maxError = 0, meanError = 0, psnr = 0;  // psnr: inf for the reference itself
  bool pareto = false;  // on the family's cost/error Pareto front
};

struct BenchResult {
  std::vector<BenchLevel> levels;
  double passThroughMs = 0, passThroughMsPerMegapixel = 0;
  std::string renderer;
  BenchSettings settings;
};

// A command-line choice that names nothing (--family nosuch): a usage error (exit 2), found
// before anything is rendered.
struct BenchUsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Throws std::runtime_error for a bad config ("bench/variants.json: ..."), BenchUsageError
// for a --family that names no family, and rt::RuntimeError for GL problems; creates its
// own GL context.
BenchResult runBench(const BenchSettings& settings);

std::string benchMarkdown(const BenchResult& r);
// Runs gnuplot on its data and script in a private temporary folder, then writes the picture
// to `png` atomically (codegen/output_files.h); returns "" or why not (no gnuplot:
// "gnuplot not found; install gnuplot-nox (scripts/setup.sh)").
std::string writeBenchPlot(const BenchResult& r, const std::string& png);

}  // namespace wg::accuracy
