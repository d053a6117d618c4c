#pragma once
// `watergraph probe`: one output of a graph evaluated per case on the GPU in float32
// (accuracy/probe_gpu.h) and by the double reference (codegen/cpu_backend.h), compared.
// A case passes when both results are finite, every component's error is within the
// error bound (accuracy/error_bound.h: |gpu - ref| <= tol * max(1, |ref|) + conditioning)
// and, if the case gives a range, both lie in it. The tolerance is the case's, else the
// file's, else the largest of the probed ops' documented node tolerances; the
// conditioning term is measured on the reference with the ops' largest condition roundings.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "accuracy/probe_cases.h"
#include "codegen/emit_glsl.h"
#include "codegen/probe_program.h"
#include "codegen/target.h"
#include "core/diagnostic.h"
#include "core/graph.h"

namespace wg::accuracy {

struct ProbeCaseResult {
  std::string name;
  std::string expect;
  int components = 1;
  std::array<double, 4> gpu{};
  std::array<double, 4> reference{};
  double absError = 0;  // of the component closest to (or furthest past) its bound
  double relError = 0;  // abs / |ref| of the same component (inf where ref = 0 and abs > 0)
  double tolerance = 0;
  double conditioning = 0;  // of the reported component
  double bound = 0;         // tolerance * max(1, |ref|) + conditioning, of the reported component
  bool gpuFinite = true, referenceFinite = true, inRange = true, withinTolerance = true;
  std::optional<std::pair<double, double>> range;
  bool passed() const { return gpuFinite && referenceFinite && inRange && withinTolerance; }
  std::string failure() const;  // "" when passed, else why: "GPU NaN/Inf", "error 3e-4 > 1e-5", ...
};

struct ProbeReport {
  std::string graph;   // file
  std::string output;  // "wave.normal" or "fragment.color"
  Type type = Type::Float;
  std::string target = "glsl330";  // the executor's target label ("glsl330", "vk450", "wgsl")
  std::string renderer;  // GL_RENDERER, the Vulkan device or the WebGPU adapter
  std::vector<ProbeCaseResult> cases;
  bool passed() const;
  int failures() const;
};

// A text edit of the probe shader, for mutation testing: every occurrence of `find` (one
// line's text, e.g. a constant as the node's GLSL writes it) becomes `replace`. A probe
// with a mutation whose `find` is not in the shader throws std::invalid_argument, so a
// mutation that changes nothing cannot pass as one the suite survived.
struct ShaderMutation {
  std::string find, replace;
  bool active() const { return !find.empty(); }
};

// Applies `m` to every stage of `shader` (see ShaderMutation).
void applyMutation(EmitResult& shader, const ShaderMutation& m);
// Applies `m` to one text: whether `find` occurred. The user's deliberate edit of a shader,
// the one place a shader's text is searched outside tests; std::invalid_argument for a
// `find` or `replace` spanning lines.
bool mutateText(std::string& text, const ShaderMutation& m);

class GpuExecutor;

// Builds the probe program and shader for the executor's target, checks the cases'
// parameter names against the graph (WG060 at the case), runs the cases on the executor
// (accuracy/gpu_executor.h) and in double. nullopt with diagnostics for graph or case
// problems; throws rt::RuntimeError for driver problems.
std::optional<ProbeReport> probeGraph(const Graph& graph, const ProbeOutput& output, const ProbeCaseFile& cases,
                                      GpuExecutor& executor, Diagnostics& diags, const ShaderMutation& mutation = {});
// The same on the current GL context, whose API must match `target` (glsl330 or es300).
std::optional<ProbeReport> probeGraph(const Graph& graph, const ProbeOutput& output, const ProbeCaseFile& cases,
                                      Target target, Diagnostics& diags, const ShaderMutation& mutation = {});

// x in [lo, hi] give or take tolerance * max(1, |bound|).
bool withinRange(double x, const std::pair<double, double>& range, double tolerance);

std::string formatProbeText(const ProbeReport& report);
nlohmann::json probeJson(const ProbeReport& report);

}  // namespace wg::accuracy
