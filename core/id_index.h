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
    std::size_t h = std::hash<std::string_view>{}(name);
    for (std::size_t i = h & mask();; i = (i + 1) & mask()) {
      const Slot& s = slots_[i];
      if (s.value < 0) return -1;
      if (s.hash == h && s.size == name.size() && std::string_view(s.data, s.size) == name) return s.value;
    }
  }

  // Stores name -> index unless the name is there: returns the index stored for it (the
  // earlier one when it was there) and whether this call stored it.
  std::pair<int, bool> emplace(std::string_view name, int index) {
    if (2 * (size_ + 1) > slots_.size()) rehash(slots_.empty() ? 16 : 2 * slots_.size());
    std::size_t h = std::hash<std::string_view>{}(name);
    for (std::size_t i = h & mask();; i = (i + 1) & mask()) {
      Slot& s = slots_[i];
      if (s.value < 0) {
        s = {name.data(), name.size(), h, index};
        ++size_;
        return {index, true};
      }
      if (s.hash == h && s.size == name.size() && std::string_view(s.data, s.size) == name) return {s.value, false};
    }
  }

 private:
  struct Slot {
    const char* data = nullptr;
    std::size_t size = 0;
    std::size_t hash = 0;
    int value = -1;  // -1: empty (indices are never negative)
  };

  std::size_t mask() const { return slots_.size() - 1; }

  void rehash(std::size_t capacity) {  // capacity: a power of two
    std::vector<Slot> old = std::move(slots_);
    slots_.assign(capacity, Slot{});
    for (const Slot& s : old) {
      if (s.value < 0) continue;
      std::size_t i = s.hash & mask();
      while (slots_[i].value >= 0) i = (i + 1) & mask();
      slots_[i] = s;
    }
  }

  std::vector<Slot> slots_;  // size: 0 or a power of two
  std::size_t size_ = 0;
};

}  // namespace wg
