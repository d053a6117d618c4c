#pragma once
// Values resolve gives to many ops, held once per distinct value: the constants of literal
// inputs and port defaults, and complete node options. A large graph repeats a few of each,
// and a copy per op was an allocation (or a JSON map and its strings) per op, kept for the
// life of the Program and copied with it.
#include <memory>
#include <unordered_map>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/node_options.h"
#include "core/value.h"

namespace wg {

struct NodeSpec;

// Constants by every bit of their components (-0.0 stays apart from 0.0, as cse keeps it).
class ConstantTable {
 public:
  std::shared_ptr<const Value> intern(const Value& v);

 private:
  // Open addressing in one flat array, at most three quarters full. A map of buckets
  // allocated a node and a vector for every distinct constant, and a large graph's literals
  // are mostly distinct: two of the three allocations per constant, and the map's lookups
  // and rehashes were about 6 % of resolving a 10,000-node graph.
  struct Slot {
    std::size_t hash = 0;
    std::shared_ptr<const Value> value;  // null: empty
  };
  void grow();
  std::vector<Slot> slots_;  // size: 0 or a power of two
  std::size_t size_ = 0;
  int shift_ = 64;  // 64 - log2(slots_.size()): a slot is the top bits of hash * a golden-ratio constant
};

// A node type's complete options and the same parsed into its struct, one pair per
// distinct (type, options).
struct SharedOptions {
  std::shared_ptr<const nlohmann::json> json;
  std::shared_ptr<const ParsedOptions> parsed;
};

class OptionsTable {
 public:
  // `complete` must be valid for `spec` (parseOptions is called on the first of its kind).
  SharedOptions intern(const NodeSpec& spec, nlohmann::json complete);

 private:
  struct Entry {
    const NodeSpec* spec;
    SharedOptions options;
  };
  std::unordered_map<size_t, std::vector<Entry>> byHash_;
};

}  // namespace wg
