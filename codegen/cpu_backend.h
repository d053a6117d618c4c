#pragma once
// The double-precision reference: a Program interpreted through each node's `eval`. The
// fold pass, the probe and the accuracy checks use it, so the reference is part of the
// compiler, not a second implementation beside it.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/program.h"

namespace wg {

class TextureCache;

// Evaluates one op given its input values (converted to the op's port types here).
// `textures` and `graphDir` serve nodes that sample textures; null only for ops that don't.
std::vector<Value> evaluateOp(const Op& op, const std::vector<Value>& inputs, const EvalEnvironment& env,
                              TextureCache* textures = nullptr, const std::string& graphDir = {});

// Evaluates one node on its own, set up as resolve would: options completed with their
// defaults, inputs not given taken from their defaults or `env`'s builtins, port types by
// the node's rules (core/port_typing.h). Throws std::invalid_argument when an input is
// missing, an input or option name is not the node's, an option value is invalid, or the
// types do not fit. For tests, hard cases and probes of a single node.
std::vector<Value> evaluateNode(const NodeSpec& spec, const nlohmann::json& options,
                                const std::vector<std::pair<std::string, Value>>& inputs, const EvalEnvironment& env,
                                TextureCache* textures = nullptr, const std::string& graphDir = {});

struct CpuResult {
  std::vector<std::vector<Value>> opOutputs;  // per op, per output port
  std::vector<Value> outputs;                 // per program output, same order
};

// Node texture look-ups made elsewhere (by the GPU, read back: accuracy/readback.h), per
// texture source ("builtin:foam", a PNG path) in the order the program's ops make them.
using TextureFetches = std::map<std::string, std::vector<Value>>;

// How `check` bounds the device's filtering precision (accuracy/error_bound.h): the node
// texture look-ups the reference samples itself (not given as fetches) are counted in
// order, and the `nudged`-th one moves each component by `fraction` times its
// filterUncertainty (nodes/texture_sampling.h).
struct FilterNudge {
  int nudged = -1;
  double fraction = 0;
  int count = 0;  // such look-ups in the last evaluation
};

// Evaluates the whole program. `parameters` overrides defaults by index (empty: defaults).
// With `fetches`, a look-up of a listed source returns its next value instead of sampling
// the image (std::logic_error when the list runs out).
CpuResult evaluateProgram(const Program& program, const EvalEnvironment& env,
                          const std::vector<Value>& parameters = {}, const TextureFetches* fetches = nullptr,
                          FilterNudge* nudge = nullptr);

}  // namespace wg
