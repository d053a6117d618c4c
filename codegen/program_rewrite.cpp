// Shared mechanics of the passes: reachability and renumbering after removal.
#include "codegen/passes.h"

namespace wg {

std::vector<bool> reachableOps(const Program& program) {
  std::vector<bool> live(program.ops.size(), false);
  for (const auto& out : program.outputs)
    if (out.value.kind == ValueRef::Kind::Op) live[static_cast<size_t>(out.value.index)] = true;
  // Ops are topological, so one backwards sweep propagates liveness to every input.
  for (size_t i = program.ops.size(); i-- > 0;) {
    if (!live[i]) continue;
    for (const auto& in : program.ops[i].inputs)
      if (in.kind == ValueRef::Kind::Op) live[static_cast<size_t>(in.index)] = true;
  }
  return live;
}

void forwardReplacedInputs(Op& op, const std::vector<std::vector<ValueRef>>& replace) {
  for (auto& in : op.inputs)
    if (in.kind == ValueRef::Kind::Op && !replace[static_cast<size_t>(in.index)].empty())
      in = replace[static_cast<size_t>(in.index)][static_cast<size_t>(in.port)];
}

void rewriteProgram(Program& program, const std::vector<std::vector<ValueRef>>& replace,
                    const std::vector<bool>& keep) {
  std::vector<int> newIndex(program.ops.size(), -1);
  int next = 0;
  for (size_t i = 0; i < program.ops.size(); ++i)
    if (keep[i]) newIndex[i] = next++;
  auto map = [&](ValueRef& ref) {
    // Replacements may chain (an op merged into one that was itself folded).
    while (ref.kind == ValueRef::Kind::Op) {
      const auto& r = replace[static_cast<size_t>(ref.index)];
      if (r.empty() || r[static_cast<size_t>(ref.port)].kind == ValueRef::Kind::None) break;
      ref = r[static_cast<size_t>(ref.port)];
    }
    if (ref.kind == ValueRef::Kind::Op) ref.index = newIndex[static_cast<size_t>(ref.index)];
  };
  // Compacted in place: kept ops move down over the removed ones (a kept op's new index is
  // never above its old one). A new array per rewrite was a fresh allocation of the whole op
  // list, megabytes at 10,000 ops, for each pass that changed anything.
  size_t w = 0;
  for (size_t i = 0; i < program.ops.size(); ++i) {
    if (!keep[i]) continue;
    if (w != i) program.ops[w] = std::move(program.ops[i]);
    for (auto& in : program.ops[w].inputs) map(in);
    ++w;
  }
  program.ops.erase(program.ops.begin() + static_cast<std::ptrdiff_t>(w), program.ops.end());
  for (auto& out : program.outputs) map(out.value);
}

}  // namespace wg
