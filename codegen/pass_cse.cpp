// cse: two ops of the same type with the same options and the same inputs compute the same
// values; the later one is replaced by the earlier. Ops are topological, so one forward
// sweep with inputs already rewritten catches chains of duplicates.
#include <bit>
#include <cstdint>
#include <functional>
#include <string_view>
#include <unordered_set>

#include "codegen/passes.h"

namespace wg {
namespace {

size_t mixHash(size_t seed, size_t v) { return seed ^ (v + 0x9e3779b97f4a7c15ull + (seed << 6) + (seed >> 2)); }

// Constants compare by every bit of their components, so equal means the same value
// (-0.0 is not 0.0: 1 / x tells them apart).
bool sameConstant(const Value& a, const Value& b) {
  if (a.type != b.type || a.size() != b.size()) return false;
  for (int i = 0; i < a.size(); ++i)
    if (std::bit_cast<uint64_t>(a[i]) != std::bit_cast<uint64_t>(b[i])) return false;
  return true;
}

bool sameRef(const ValueRef& a, const ValueRef& b) {
  if (a.kind != b.kind) return false;
  switch (a.kind) {
    case ValueRef::Kind::Op: return a.index == b.index && a.port == b.port;
    case ValueRef::Kind::Param:
    case ValueRef::Kind::Builtin: return a.index == b.index;
    case ValueRef::Kind::Const: return sameConstant(a.constant(), b.constant());
    case ValueRef::Kind::None: return true;
  }
  return false;
}

size_t refHash(const ValueRef& r) {
  size_t h = static_cast<size_t>(r.kind);
  switch (r.kind) {
    case ValueRef::Kind::Op: return mixHash(mixHash(h, static_cast<size_t>(r.index)), static_cast<size_t>(r.port));
    case ValueRef::Kind::Param:
    case ValueRef::Kind::Builtin: return mixHash(h, static_cast<size_t>(r.index));
    case ValueRef::Kind::Const:
      h = mixHash(h, static_cast<size_t>(r.constant().type));
      for (int i = 0; i < r.constant().size(); ++i) h = mixHash(h, std::bit_cast<uint64_t>(r.constant()[i]));
      return h;
    case ValueRef::Kind::None: return h;
  }
  return h;
}

// What an op computes: its type, options, inputs and input types (not its id or place).
size_t computationHash(const Op& op) {
  size_t h = std::hash<std::string_view>{}(op.spec->type);
  if (!op.options().empty()) h = mixHash(h, std::hash<nlohmann::json>{}(op.options()));
  for (const auto& in : op.inputs) h = mixHash(h, refHash(in));
  for (Type t : op.inputTypes) h = mixHash(h, static_cast<size_t>(t));
  return h;
}

bool sameComputation(const Op& a, const Op& b) {
  if (a.spec != b.spec && a.spec->type != b.spec->type) return false;
  if (a.inputTypes != b.inputTypes || a.inputs.size() != b.inputs.size()) return false;
  for (size_t k = 0; k < a.inputs.size(); ++k)
    if (!sameRef(a.inputs[k], b.inputs[k])) return false;
  return a.options() == b.options();
}

}  // namespace

PassResult csePass(Program& program, PassContext&) {
  size_t n = program.ops.size();
  std::vector<std::vector<ValueRef>> replace(n);
  std::vector<bool> keep(n, true);
  // Ops by what they compute: hashed structurally (no key text per op; a 10,000-op
  // program spent most of this pass writing and hashing strings).
  std::vector<size_t> hashes(n, 0);
  auto hashOf = [&](int i) { return hashes[static_cast<size_t>(i)]; };
  auto equal = [&](int a, int b) { return sameComputation(program.ops[static_cast<size_t>(a)], program.ops[static_cast<size_t>(b)]); };
  std::unordered_set<int, decltype(hashOf), decltype(equal)> seen(n, hashOf, equal);
  bool changed = false;
  for (size_t i = 0; i < n; ++i) {
    Op& op = program.ops[i];
    forwardReplacedInputs(op, replace);
    hashes[i] = computationHash(op);
    auto [it, inserted] = seen.insert(static_cast<int>(i));
    if (inserted) continue;
    Op& first = program.ops[static_cast<size_t>(*it)];
    for (size_t p = 0; p < op.outputTypes.size(); ++p)
      replace[i].push_back(ValueRef::op(*it, static_cast<int>(p)));
    first.mergedIds.push_back(op.nodeId);
    program.removed.push_back({op.nodeId, "merged into '" + first.nodeId + "' (same computation)"});
    keep[i] = false;
    changed = true;
  }
  if (changed) rewriteProgram(program, replace, keep);
  return changed ? PassResult::Changed : PassResult::Unchanged;
}

}  // namespace wg
