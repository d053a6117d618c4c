#pragma once
// The Program `watergraph probe` runs: the graph's ops reaching one chosen output (a node
// output "NODE.PORT", or the fragment colour), after the same passes a compile runs, with
// every op in the fragment stage (the probe shader is one full-screen fragment shader;
// see EmitMode::Probe), so the GPU and the double reference evaluate the same ops.
#include <optional>
#include <string>

#include "core/diagnostic.h"
#include "core/graph.h"
#include "core/program.h"
#include "core/registry.h"

namespace wg {

struct ProbeOutput {
  std::string node;  // "" = the graph's fragment colour
  std::string port;  // "" = the node's first output
};

// "wave.normal" -> {wave, normal}; "wave" -> {wave, ""}. Returns nullopt for an empty
// node or port part.
std::optional<ProbeOutput> parseProbeOutput(const std::string& text);

// Resolve, passes (specialise, prune, fold/simplify/cse, prune), all ops in the fragment
// stage. An unknown node or port is WG025 at the graph file with a suggestion; a graph
// without a fragment colour and no `output` is WG031.
std::optional<Program> buildProbeProgram(const Graph& graph, const Registry& registry, const ProbeOutput& output,
                                         Diagnostics& diags);

}  // namespace wg
