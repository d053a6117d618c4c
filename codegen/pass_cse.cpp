// cse: two ops of the same type with the same options and the same inputs compute the same
// values; the later one is replaced by the earlier. Ops are topological, so one forward
// sweep with inputs already rewritten catches chains of duplicates.
#include <charconv>
#include <unordered_map>

#include "codegen/passes.h"
#include "core/number_format.h"

namespace wg {
namespace {

void appendInt(std::string& out, long long v) {
  char buf[24];
  auto end = std::to_chars(buf, buf + sizeof buf, v).ptr;
  out.append(buf, end);
}

// Appends a reference's identity. Constants keep every bit of their components (a
// double's bits), so equal keys mean equal values.
void appendRefKey(std::string& out, const ValueRef& r) {
  switch (r.kind) {
    case ValueRef::Kind::Op: out += 'o'; appendInt(out, r.index); out += '.'; appendInt(out, r.port); return;
    case ValueRef::Kind::Param: out += 'p'; appendInt(out, r.index); return;
    case ValueRef::Kind::Builtin: out += 'b'; appendInt(out, r.index); return;
    case ValueRef::Kind::Const:
      out += 'c';
      out += typeName(r.constant.type);
      for (int i = 0; i < r.constant.size(); ++i) {
        out += ',';
        out += formatNumber(r.constant[i]);
      }
      return;
    case ValueRef::Kind::None: out += '-'; return;
  }
}

}  // namespace

PassResult csePass(Program& program, PassContext&) {
  size_t n = program.ops.size();
  std::vector<std::vector<ValueRef>> replace(n);
  std::vector<bool> keep(n, true);
  // Hashed keys: a sorted map compares long shared prefixes and grew faster than linear.
  std::unordered_map<std::string, int> seen;
  seen.reserve(n);
  bool changed = false;
  std::string key;
  for (size_t i = 0; i < n; ++i) {
    Op& op = program.ops[i];
    for (auto& in : op.inputs)
      if (in.kind == ValueRef::Kind::Op && !replace[static_cast<size_t>(in.index)].empty())
        in = replace[static_cast<size_t>(in.index)][static_cast<size_t>(in.port)];
    key.clear();
    key += op.spec->type;
    key += '|';
    if (!op.options.empty()) key += op.options.dump();
    for (const auto& in : op.inputs) {
      key += '|';
      appendRefKey(key, in);
    }
    for (Type t : op.inputTypes) {
      key += '|';
      key += typeName(t);
    }
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
