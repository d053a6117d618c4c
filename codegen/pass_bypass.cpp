// bypass: an op whose `bypass` option is on (NodeSpec::bypass) is replaced by the values
// its node declares for "off" — an input passed through, or a constant — before any other
// pass runs, so the prune pass removes what only it needed: the ops feeding it and, with
// them, the scene resources and render passes it alone read.
#include "codegen/passes.h"

namespace wg {

static bool bypassed(const Op& op) {
  if (op.spec->bypass.empty()) return false;
  auto it = op.options().find(kBypassOption);
  return it != op.options().end() && it->is_boolean() && it->get<bool>();
}

PassResult bypassPass(Program& program, PassContext&) {
  size_t n = program.ops.size();
  std::vector<std::vector<ValueRef>> replace(n);
  std::vector<bool> keep(n, true);
  bool changed = false;
  for (size_t i = 0; i < n; ++i) {
    Op& op = program.ops[i];
    forwardReplacedInputs(op, replace);
    if (!bypassed(op)) continue;
    for (const auto& out : op.spec->outputs) {
      for (const auto& b : op.spec->bypass) {
        if (b.output != out.name) continue;
        replace[i].push_back(b.constant ? ValueRef::constant_(*b.constant)
                                        : op.inputs[static_cast<size_t>(op.spec->inputIndex(b.input))]);
      }
    }
    keep[i] = false;
    program.removed.push_back({op.nodeId, "bypassed"});
    changed = true;
  }
  if (changed) rewriteProgram(program, replace, keep);
  return changed ? PassResult::Changed : PassResult::Unchanged;
}

}  // namespace wg
