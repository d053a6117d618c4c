#pragma once
// Names to indices for resolve (node ids): an open-addressing table of views into strings
// the caller keeps alive, in one flat array. std::unordered_map allocates a node per name
// and follows a pointer on every probe; resolve looks a node id up about three times per
// node, so on a large graph the table's layout is what the lookups cost.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string_view>
#include <utility>
#include <vector>

namespace wg {

class IdIndex {
 public:
  // Room for `n` names without growing.
  void reserve(std::size_t n) {
    std::size_t want = 16;
    while (want < 2 * n) want *= 2;  // at most half full: probes stay short
    if (want > slots_.size()) rehash(want);
  }

  // The index stored for `name`, or -1.
  int find(std::string_view name) const {
    if (slots_.empty()) return -1;
    for (std::size_t i = hashOf(name) & mask();; i = (i + 1) & mask()) {
      const Slot& s = slots_[i];
      if (s.value < 0) return -1;
      if (s.name() == name) return s.value;
    }
  }

  // Stores name -> index unless the name is there: returns the index stored for it (the
  // earlier one when it was there) and whether this call stored it.
  std::pair<int, bool> emplace(std::string_view name, int index) {
    if (2 * (size_ + 1) > slots_.size()) rehash(slots_.empty() ? 16 : 2 * slots_.size());
    for (std::size_t i = hashOf(name) & mask();; i = (i + 1) & mask()) {
      Slot& s = slots_[i];
      if (s.value < 0) {
        s = {name.data(), static_cast<std::uint32_t>(name.size()), index};
        ++size_;
        return {index, true};
      }
      if (s.name() == name) return {s.value, false};
    }
  }

 private:
  // 16 bytes: a table at most half full of 10,000 ids is 32,768 slots, and with the hash
  // kept beside each name (32 bytes a slot) it was a megabyte of the compile's peak heap.
  // Without it a probe compares the lengths first, and the ids that share a slot's run
  // rarely share a length and a first byte.
  struct Slot {
    const char* data = nullptr;
    std::uint32_t size = 0;  // a name from a file of at most 16 MiB
    int value = -1;          // -1: empty (indices are never negative)
    std::string_view name() const { return {data, size}; }
  };

  static std::size_t hashOf(std::string_view name) { return std::hash<std::string_view>{}(name); }

  std::size_t mask() const { return slots_.size() - 1; }

  void rehash(std::size_t capacity) {  // capacity: a power of two
    std::vector<Slot> old = std::move(slots_);
    slots_.assign(capacity, Slot{});
    for (const Slot& s : old) {
      if (s.value < 0) continue;
      std::size_t i = hashOf(s.name()) & mask();
      while (slots_[i].value >= 0) i = (i + 1) & mask();
      slots_[i] = s;
    }
  }

  std::vector<Slot> slots_;  // size: 0 or a power of two
  std::size_t size_ = 0;
};

}  // namespace wg
