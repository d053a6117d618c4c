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

}  // namespace

std::shared_ptr<const Value> ConstantTable::intern(const Value& v) {
  size_t h = static_cast<size_t>(v.type);
  for (int i = 0; i < v.size(); ++i) h = mix(h, std::bit_cast<uint64_t>(v[i]));
  auto& bucket = byHash_[h];
  for (const auto& held : bucket)
    if (sameBits(*held, v)) return held;
  bucket.push_back(std::make_shared<const Value>(v));
  return bucket.back();
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
