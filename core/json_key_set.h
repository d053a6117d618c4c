#pragma once
// The keys an open JSON object has seen, first occurrences only, to find duplicates
// (WG003). Scanned while small; big objects (a graph's "parameters") get a hash index.
// Shared by the two readers of JSON events (core/json_events.cpp, core/json_fast_read.cpp).
#include <cstddef>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/json_event_handler.h"

namespace wg {

class JsonKeySet {
 public:
  void clear() {
    count_ = 0;
    index_.clear();
  }
  // The first occurrence's position if `name` was seen; else records it.
  const JsonPosition* seenOrAdd(const std::string& name, JsonPosition at) {
    constexpr std::size_t kScanLimit = 16;
    if (count_ < kScanLimit) {
      for (std::size_t i = 0; i < count_; ++i)
        if (keys_[i].name == name) return &keys_[i].at;
      if (keys_.size() <= count_) keys_.emplace_back();
      keys_[count_].name = name;  // the slot's string keeps its capacity between objects
      keys_[count_].at = at;
      ++count_;
      return nullptr;
    }
    if (index_.empty())
      for (std::size_t i = 0; i < count_; ++i) index_.emplace(keys_[i].name, keys_[i].at);
    auto [it, inserted] = index_.try_emplace(name, at);
    return inserted ? nullptr : &it->second;
  }

 private:
  struct Seen {
    std::string name;
    JsonPosition at;
  };
  std::vector<Seen> keys_;
  std::size_t count_ = 0;
  std::unordered_map<std::string, JsonPosition> index_;
};

}  // namespace wg
