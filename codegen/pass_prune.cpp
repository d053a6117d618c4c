// prune: only what the outputs reach survives — ops, and the parameters (uniforms) they
// read. Everything removed is recorded for the manifest.
#include "codegen/passes.h"

namespace wg {

PassResult prunePass(Program& program, PassContext&) {
  std::vector<bool> live = reachableOps(program);
  bool changed = false;
  for (size_t i = 0; i < program.ops.size(); ++i)
    if (!live[i]) {
      program.removed.push_back({program.ops[i].nodeId, "unreachable from the outputs"});
      changed = true;
    }
  if (changed) rewriteProgram(program, std::vector<std::vector<ValueRef>>(program.ops.size()), live);

  // Parameters no surviving op or output reads are dropped (renumbered).
  std::vector<bool> used(program.parameters.size(), false);
  auto mark = [&](const ValueRef& r) {
    if (r.kind == ValueRef::Kind::Param) used[static_cast<size_t>(r.index)] = true;
  };
  for (const auto& op : program.ops)
    for (const auto& in : op.inputs) mark(in);
  for (const auto& out : program.outputs) mark(out.value);
  std::vector<int> newIndex(program.parameters.size(), -1);
  std::vector<ProgramParameter> kept;
  for (size_t i = 0; i < program.parameters.size(); ++i) {
    if (!used[i]) {
      const auto& p = program.parameters[i];
      program.removed.push_back({"$" + p.name, p.isStatic ? "static: compiled in as a constant" : "unused"});
      changed = true;
      continue;
    }
    newIndex[i] = static_cast<int>(kept.size());
    kept.push_back(std::move(program.parameters[i]));
  }
  program.parameters = std::move(kept);
  auto remap = [&](ValueRef& r) {
    if (r.kind == ValueRef::Kind::Param) r.index = newIndex[static_cast<size_t>(r.index)];
  };
  for (auto& op : program.ops)
    for (auto& in : op.inputs) remap(in);
  for (auto& out : program.outputs) remap(out.value);
  return changed ? PassResult::Changed : PassResult::Unchanged;
}

}  // namespace wg
