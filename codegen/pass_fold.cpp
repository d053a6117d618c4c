// fold: an op whose inputs are all constants is evaluated at compile time by its double
// `eval` — the same reference the accuracy checks use — and its uses become constants.
// Sources (builtins, textures, time) are never folded.
#include <cmath>

#include "codegen/cpu_backend.h"
#include "codegen/passes.h"

namespace wg {

PassResult foldPass(Program& program, PassContext&) {
  size_t n = program.ops.size();
  std::vector<std::vector<ValueRef>> replace(n);
  std::vector<bool> keep(n, true);
  bool changed = false;
  EvalEnvironment env;  // unused by foldable ops: they read no builtins
  for (size_t i = 0; i < n; ++i) {
    Op& op = program.ops[i];
    // Inputs folded earlier in this sweep are substituted first.
    for (auto& in : op.inputs)
      if (in.kind == ValueRef::Kind::Op && !replace[static_cast<size_t>(in.index)].empty())
        in = replace[static_cast<size_t>(in.index)][static_cast<size_t>(in.port)];
    // A function node's GLSL is the truth and its reference (if any) a check of it: never folded.
    if (op.spec->isSource || op.spec->ownGlsl) continue;
    bool allConst = true;
    for (const auto& in : op.inputs) allConst &= in.kind == ValueRef::Kind::Const;
    if (!allConst) continue;
    std::vector<Value> inputs;
    for (const auto& in : op.inputs) inputs.push_back(in.constant());
    std::vector<Value> outs = evaluateOp(op, inputs, env);
    // A non-finite or float-overflowing result stays a GPU computation, so the shader
    // behaves exactly as the unfolded one would (no inf literal can be written).
    bool representable = true;
    for (const auto& v : outs)
      for (int c = 0; c < v.size(); ++c)
        representable &= std::isfinite(v[c]) && std::fabs(v[c]) <= 3.4028234663852886e38;
    if (!representable) continue;
    for (size_t p = 0; p < outs.size(); ++p) replace[i].push_back(ValueRef::constant_(outs[p]));
    keep[i] = false;
    program.removed.push_back({op.nodeId, "folded: constant at compile time"});
    changed = true;
  }
  if (changed) rewriteProgram(program, replace, keep);
  return changed ? PassResult::Changed : PassResult::Unchanged;
}

}  // namespace wg
