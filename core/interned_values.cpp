#include "core/interned_values.h"

#include <bit>
#include <cstdint>
#include <functional>

#include "core/node_spec.h"

namespace wg {
namespace {

size_t mix(size_t seed, size_t v) { return seed ^ (v + 0x9e3779b97f4a7c15ull + (seed << 6) + (seed >> 2)); }

bool sameBits(const Value& a, const Value& b) {
  if (a.type != b.type) return false;
  for (int i = 0; i < a.size(); ++i)
    if (std::bit_cast<uint64_t>(a[i]) != std::bit_cast<uint64_t>(b[i])) return false;
  return true;
}

// The slot a hash starts probing at: its top bits after a multiply, since mix() keeps the
// low bits of a double's mantissa, which are zero for most short literals.
std::size_t constantSlot(std::size_t hash, int shift) {
  return static_cast<std::size_t>((static_cast<uint64_t>(hash) * 0x9e3779b97f4a7c15ull) >> shift);
}

}  // namespace

std::shared_ptr<const Value> ConstantTable::intern(const Value& v) {
  size_t h = static_cast<size_t>(v.type);
  for (int i = 0; i < v.size(); ++i) h = mix(h, std::bit_cast<uint64_t>(v[i]));
  if (4 * (size_ + 1) > 3 * slots_.size()) grow();
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t i = constantSlot(h, shift_);; i = (i + 1) & mask) {
    Slot& s = slots_[i];
    if (!s.value) {
      s = {h, std::make_shared<const Value>(v)};
      ++size_;
      return s.value;
    }
    if (s.hash == h && sameBits(*s.value, v)) return s.value;
  }
}

void ConstantTable::grow() {
  std::vector<Slot> old = std::move(slots_);
  const std::size_t capacity = old.empty() ? 64 : 2 * old.size();
  slots_.assign(capacity, Slot{});
  shift_ = 64 - std::countr_zero(capacity);
  for (Slot& s : old) {
    if (!s.value) continue;
    std::size_t i = constantSlot(s.hash, shift_);
    while (slots_[i].value) i = (i + 1) & (capacity - 1);
    slots_[i] = std::move(s);
  }
}

SharedOptions OptionsTable::intern(const NodeSpec& spec, nlohmann::json complete) {
  size_t h = mix(std::hash<const NodeSpec*>{}(&spec), std::hash<nlohmann::json>{}(complete));
  auto& bucket = byHash_[h];
  for (const auto& e : bucket)
    if (e.spec == &spec && *e.options.json == complete) return e.options;
  auto json = std::make_shared<const nlohmann::json>(std::move(complete));
  auto parsed = parseOptions(spec, *json);
  bucket.push_back({&spec, {std::move(json), std::move(parsed)}});
  return bucket.back().options;
}

}  // namespace wg
