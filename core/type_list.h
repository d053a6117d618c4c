#pragma once
// The port types of one op (or of a node being typed): a short list of one-byte Types held
// inline. Every op of a Program has two of them, and as std::vector<Type> each was a heap
// block of a few bytes, allocated while typing the node, copied through `infer` and freed
// with the op: at 10,000 nodes, tens of thousands of allocations and about 0.6 MiB of
// blocks for what fits in the op itself. A list longer than the inline room moves to the
// heap (no registered node has one: the widest, `underwater`, has 16 inputs). Same size as
// a std::vector.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <iterator>
#include <stdexcept>
#include <vector>

#include "core/types.h"

namespace wg {

class TypeList {
 public:
  static constexpr std::size_t kInline = 16;

  TypeList() = default;
  TypeList(std::size_t n, Type t) { assign(n, t); }
  TypeList(std::initializer_list<Type> types) { assign(types.begin(), types.end()); }
  TypeList(const std::vector<Type>& types) { assign(types.begin(), types.end()); }  // NOLINT(google-explicit-constructor)
  TypeList(const TypeList& o) { assign(o.begin(), o.end()); }
  TypeList(TypeList&& o) noexcept { take(o); }
  ~TypeList() { release(); }
  TypeList& operator=(const TypeList& o) {
    if (this != &o) assign(o.begin(), o.end());
    return *this;
  }
  TypeList& operator=(TypeList&& o) noexcept {
    if (this != &o) {
      release();
      take(o);
    }
    return *this;
  }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  Type* data() { return onHeap() ? heap_.items : inline_.data(); }
  const Type* data() const { return onHeap() ? heap_.items : inline_.data(); }
  Type* begin() { return data(); }
  Type* end() { return data() + size_; }
  const Type* begin() const { return data(); }
  const Type* end() const { return data() + size_; }
  Type& operator[](std::size_t i) { return data()[i]; }
  Type operator[](std::size_t i) const { return data()[i]; }
  Type& at(std::size_t i) {
    if (i >= size_) throw std::out_of_range("TypeList::at");
    return data()[i];
  }
  Type at(std::size_t i) const {
    if (i >= size_) throw std::out_of_range("TypeList::at");
    return data()[i];
  }

  void push_back(Type t) {
    reserve(size_ + 1);
    data()[size_++] = t;
  }
  void resize(std::size_t n, Type t = Type::Invalid) {
    reserve(n);
    for (std::size_t i = size_; i < n; ++i) data()[i] = t;
    size_ = static_cast<std::uint32_t>(n);
  }
  void assign(std::size_t n, Type t) {
    size_ = 0;
    resize(n, t);
  }
  template <class It>
  void assign(It first, It last) {
    std::size_t n = static_cast<std::size_t>(std::distance(first, last));
    size_ = 0;
    reserve(n);
    std::copy(first, last, data());
    size_ = static_cast<std::uint32_t>(n);
  }

  friend bool operator==(const TypeList& a, const TypeList& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end());
  }

 private:
  bool onHeap() const { return capacity_ > kInline; }
  std::size_t capacity() const { return onHeap() ? capacity_ : kInline; }
  void reserve(std::size_t n) {
    if (n <= capacity()) return;
    if (n > UINT32_MAX) throw std::length_error("TypeList: too many ports");
    std::size_t cap = std::min<std::size_t>(std::max(n, 2 * capacity()), UINT32_MAX);
    Type* grown = new Type[cap];
    std::copy(begin(), end(), grown);
    release();
    heap_.items = grown;
    capacity_ = static_cast<std::uint32_t>(cap);
  }
  void release() {
    if (onHeap()) delete[] heap_.items;
    capacity_ = 0;
  }
  void take(TypeList& o) {
    size_ = o.size_;
    capacity_ = o.capacity_;
    if (o.onHeap()) heap_.items = o.heap_.items;
    else inline_ = o.inline_;
    o.size_ = 0;
    o.capacity_ = 0;
  }

  union {
    std::array<Type, kInline> inline_{};
    struct {
      Type* items;
    } heap_;
  };
  std::uint32_t size_ = 0;
  std::uint32_t capacity_ = 0;  // <= kInline: inline; else the heap block's length
};

static_assert(sizeof(TypeList) == sizeof(std::vector<Type>), "an op holds two: no larger than the vectors they replace");

}  // namespace wg
