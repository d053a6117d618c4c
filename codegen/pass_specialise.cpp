// specialise: parameters marked "static" are compile-time constants. Replacing their uses
// with constants lets fold evaluate what depends only on them, so they cost nothing.
#include "codegen/passes.h"

namespace wg {

PassResult specialisePass(Program& program, PassContext&) {
  bool changed = false;
  auto substitute = [&](ValueRef& ref) {
    if (ref.kind != ValueRef::Kind::Param) return;
    const ProgramParameter& p = program.parameters[static_cast<size_t>(ref.index)];
    if (!p.isStatic) return;
    ref = ValueRef::constant_(p.defaultValue);
    changed = true;
  };
  for (auto& op : program.ops)
    for (auto& in : op.inputs) substitute(in);
  for (auto& out : program.outputs) substitute(out.value);
  return changed ? PassResult::Changed : PassResult::Unchanged;
}

}  // namespace wg
