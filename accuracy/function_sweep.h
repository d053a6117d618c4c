#pragma once
// The hard-case sweep of GLSL function nodes (docs/accuracy.md, "Function nodes"). A
// glsl_function node's ports come from its file, so the suite cannot name them as it names
// a registered node's: instead each input port in turn takes every value class the suite's
// cases give an input of that type (tests/hardcases/suite.json: zero vectors, huge and tiny
// values, negatives, the boundaries of the math nodes; a float class also splatted to the
// vector and matrix types), the other inputs held at 0.5, and every output of the node's
// own GLSL is read back from the GPU (one probe pixel per case, as for any node) and
// checked for NaN/Inf. Where the node has a reference formula the probe's error
// comparison applies too (accuracy/probe.h); without one, finiteness is all there is to
// check, and the result says so. A sampler2D parameter is not swept: it is held at the
// built-in texture the node names, else (a PNG) at its option's default built-in texture.
// An output of a matrix type is not read back (a probe pixel holds four components); the
// result notes it.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "accuracy/probe.h"

namespace wg::accuracy {

// One value an input port is swept over: from the suite case and port that give it
// ("zero_normal.normal"), or a float class splatted to a wider type ("log_of_zero.x splat").
struct FunctionInputClass {
  std::string name;
  Value value;  // float32, every component finite
};

// The suite's value classes for an input of type `t`, each value once, in case order:
// the finite `inputs` values of type `t`, then the float ones splatted (vector and matrix
// types). Non-finite values are left out: the sweep asks whether finite inputs give a
// finite result.
std::vector<FunctionInputClass> functionInputClasses(const ProbeCaseFile& suite, Type t);

// A glsl_function node of a graph (or of a subgraph it instantiates), as the sweep probes it.
struct FunctionNodeUnderTest {
  std::string label;      // "node 'caustic' (graphs/lib/caustic_light.json, function 'caustic')"
  std::string graphFile;  // the graph file that holds the node: its .glsl file lies beside it
  std::shared_ptr<const NodeSpec> spec;
  nlohmann::json options;  // file, function, reference (when it has one), each sampler at a built-in texture
  bool hasReference = false;
};

// The glsl_function nodes `graph` resolves to, each once (two instances of one subgraph
// give one node). nullopt with diagnostics when the graph does not resolve.
std::optional<std::vector<FunctionNodeUnderTest>> functionNodesOf(const Graph& graph, Diagnostics& diags);

// One input class of one port run through one output of a node.
struct FunctionSweepCase {
  std::string node;    // FunctionNodeUnderTest::label
  std::string output;  // the output port
  std::string port;    // the input port swept
  std::string inputClass;
  Value input;
  int components = 1;
  std::array<double, 4> gpu{};
  bool compared = false;  // held to the reference formula too
  double absError = 0, bound = 0;  // with a reference: the probe's |gpu - ref| and error bound (accuracy/probe.h)
  std::string failure;    // "" when it passed: "GPU NaN/Inf", or the probe's failure() with a reference
  bool nanInf = false;
};

struct FunctionSweepResult {
  Target target = Target::Glsl330;
  int nodes = 0;
  int caseRuns = 0;  // results read back from the GPU: node x output x port x input class
  int compared = 0;  // of those, compared with a reference formula
  int failures = 0;
  int nanInf = 0;
  double worstErrorToBound = 0;  // over the compared runs
  std::string worstCase;         // "node output port=class" of that run
  std::vector<FunctionSweepCase> cases;
  std::vector<std::string> failureLines;  // one per failed case, naming node, output, port and class
  std::vector<std::string> notes;         // what was held fixed or not compared, per node
  std::vector<std::string> errors;        // outputs that could not be probed, and why
};

// Sweeps every node of `nodes` on `executor` over `suite`'s input classes.
FunctionSweepResult sweepFunctionNodes(const std::vector<FunctionNodeUnderTest>& nodes, const ProbeCaseFile& suite,
                                       GpuExecutor& executor);

// A line per failure and note, then "N function nodes, M case runs (K compared with a
// reference), F failed (X NaN/Inf)", and the worst error/bound of the compared runs.
std::string formatFunctionSweep(const FunctionSweepResult& result);

}  // namespace wg::accuracy
