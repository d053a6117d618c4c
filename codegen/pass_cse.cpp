// cse: two ops of the same type with the same options and the same inputs compute the same
// values; the later one is replaced by the earlier. Ops are topological, so one forward
// sweep with inputs already rewritten catches chains of duplicates.
#include <map>

#include "codegen/passes.h"
#include "core/number_format.h"

namespace wg {
namespace {

std::string refKey(const ValueRef& r) {
  switch (r.kind) {
    case ValueRef::Kind::Op: return "o" + std::to_string(r.index) + "." + std::to_string(r.port);
    case ValueRef::Kind::Param: return "p" + std::to_string(r.index);
    case ValueRef::Kind::Builtin: return "b" + std::to_string(r.index);
    case ValueRef::Kind::Const: {
      std::string k = "c" + std::string(typeName(r.constant.type));
      for (int i = 0; i < r.constant.size(); ++i) k += "," + formatNumber(r.constant[i]);
      return k;
    }
    case ValueRef::Kind::None: return "-";
  }
  return "?";
}

}  // namespace

PassResult csePass(Program& program, PassContext&) {
  size_t n = program.ops.size();
  std::vector<std::vector<ValueRef>> replace(n);
  std::vector<bool> keep(n, true);
  std::map<std::string, int> seen;
  bool changed = false;
  for (size_t i = 0; i < n; ++i) {
    Op& op = program.ops[i];
    for (auto& in : op.inputs)
      if (in.kind == ValueRef::Kind::Op && !replace[static_cast<size_t>(in.index)].empty())
        in = replace[static_cast<size_t>(in.index)][static_cast<size_t>(in.port)];
    std::string key = op.spec->type + "|" + op.options.dump();
    for (const auto& in : op.inputs) key += "|" + refKey(in);
    for (Type t : op.inputTypes) key += "|" + std::string(typeName(t));
    auto [it, inserted] = seen.emplace(key, static_cast<int>(i));
    if (inserted) continue;
    Op& first = program.ops[static_cast<size_t>(it->second)];
    for (size_t p = 0; p < op.outputTypes.size(); ++p)
      replace[i].push_back(ValueRef::op(it->second, static_cast<int>(p)));
    first.mergedIds.push_back(op.nodeId);
    program.removed.push_back({op.nodeId, "merged into '" + first.nodeId + "' (same computation)"});
    keep[i] = false;
    changed = true;
  }
  if (changed) rewriteProgram(program, replace, keep);
  return changed ? PassResult::Changed : PassResult::Unchanged;
}

}  // namespace wg
