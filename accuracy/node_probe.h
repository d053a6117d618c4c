#pragma once
// One node type probed alone: a graph made of that node, whose inputs the cases set
// become parameters (uniforms), so every case reaches the GPU as data and nothing folds.
// Inputs a case does not give keep the node's behaviour: their default value, or the
// builtin the port defaults to (which the case sets); a required input no case gives is
// 0.5 (splatted). Used by `watergraph probe --node` and the hard-case suite.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "accuracy/probe.h"

namespace wg::accuracy {

// The key of `options` that holds, for a node with an `ocean` input, the options of the
// ocean_spectrum node the probe feeds it from (its defaults when absent); it is not an
// option of the node itself.
inline constexpr const char* kOceanOptionsKey = "ocean";

// The graph for `spec` with `options`, its inputs as parameters "in_<port>" wherever a
// case gives the port (or it is required), and per case the parameter values. Cases that
// give a port a value of another vector size than the first case that gives it are left
// out (`skipped` gets their names).
struct NodeProbeSetup {
  Graph graph;
  ProbeCaseFile cases;
  std::vector<std::string> skipped;
};
NodeProbeSetup makeNodeProbe(const NodeSpec& spec, const nlohmann::json& options, const std::vector<ProbeCase>& cases);

// Probes output `output` ("" = the first) of `spec` on `executor`.
std::optional<ProbeReport> probeNode(const NodeSpec& spec, const nlohmann::json& options, const std::string& output,
                                     const std::vector<ProbeCase>& cases, GpuExecutor& executor, Diagnostics& diags,
                                     const ShaderMutation& mutation = {});
// The same on the current GL context, whose API must match `target` (glsl330 or es300).
std::optional<ProbeReport> probeNode(const NodeSpec& spec, const nlohmann::json& options, const std::string& output,
                                     const std::vector<ProbeCase>& cases, Target target, Diagnostics& diags,
                                     const ShaderMutation& mutation = {});

}  // namespace wg::accuracy
