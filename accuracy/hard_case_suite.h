#pragma once
// The hard-case suite (tests/hardcases/suite.json, docs/accuracy.md): every case runs
// against every node that takes such an input — a node input port the case sets, or a
// builtin or scene value the node reads and the case sets — in the node's default options
// and in each variant of its enumerated, boolean and bounded integer options (one option
// changed at a time), for every output, plus the node's own documented hard cases. Each
// run is a node probe (accuracy/node_probe.h): GPU float32 against the double reference.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "accuracy/probe.h"

namespace wg::accuracy {

struct SuiteOptions {
  std::vector<std::string> nodes;  // node types to run; empty: every registered node
  bool variants = true;            // option variants besides the defaults
  bool nodeHardCases = true;       // each node's own NodeSpec::hardCases
  // Mutation testing: the edit applied to every probe shader that contains its text; runs
  // whose shader does not are left out (SuiteResult::mutatedRuns counts the others).
  ShaderMutation mutation;
};

struct SuiteRun {
  std::string node;
  std::string variant;  // "defaults" or "model=schlick"
  nlohmann::json options;  // every option of the node in this run (defaults filled in, the cases' own applied)
  ProbeReport report;
};

struct SuiteResult {
  std::vector<SuiteRun> runs;
  int caseRuns = 0;  // case x node x variant x output evaluations
  int failures = 0;
  int nanInf = 0;    // failures that are NaN or Inf (GPU or reference)
  int mutatedRuns = 0;  // probe runs (node, variant, output) whose shader the mutation changed
  std::vector<std::string> failureLines;  // one per failed case run
  std::vector<std::string> errors;        // nodes that could not be probed, and why
};

// On `executor` (accuracy/gpu_executor.h): its target's probe shaders on its API.
SuiteResult runHardCaseSuite(const ProbeCaseFile& suite, GpuExecutor& executor, const SuiteOptions& options);
// On the current GL context, whose API must match `target` (glsl330 or es300).
SuiteResult runHardCaseSuite(const ProbeCaseFile& suite, Target target, const SuiteOptions& options);

// Which suite keys ("time", "scene.depth", ...) the node reads with its default options.
std::vector<std::string> nodeReads(const NodeSpec& spec);

}  // namespace wg::accuracy
