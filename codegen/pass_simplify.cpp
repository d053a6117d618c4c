// simplify: an op that reduces to one of its inputs for the constants it is given
// (NodeSpec::identity: x * 1, x + 0, x / 1, mix(a, b, 0)) is replaced by that input, so
// generated code carries no arithmetic a hand-written shader would not.
#include "codegen/passes.h"

namespace wg {

PassResult simplifyPass(Program& program, PassContext&) {
  size_t n = program.ops.size();
  std::vector<std::vector<ValueRef>> replace(n);
  std::vector<bool> keep(n, true);
  bool changed = false;
  std::vector<std::optional<Value>> constants;  // one op's at a time; reused, not reallocated per op
  for (size_t i = 0; i < n; ++i) {
    Op& op = program.ops[i];
    forwardReplacedInputs(op, replace);
    if (!op.spec->identity || op.outputTypes.size() != 1) continue;
    constants.clear();
    for (const auto& in : op.inputs)
      constants.push_back(in.kind == ValueRef::Kind::Const ? std::optional<Value>(in.constant()) : std::nullopt);
    int which = op.spec->identity(constants);
    if (which < 0) continue;
    const ValueRef& kept = op.inputs[static_cast<size_t>(which)];
    if (program.typeOf(kept) != op.outputTypes[0]) continue;  // a splat is not the identity
    replace[i].push_back(kept);
    keep[i] = false;
    program.removed.push_back({op.nodeId, "simplified: equals its input '" + op.spec->inputs[static_cast<size_t>(which)].name + "'"});
    changed = true;
  }
  if (changed) rewriteProgram(program, replace, keep);
  return changed ? PassResult::Changed : PassResult::Unchanged;
}

}  // namespace wg
