// Replaces the global operator new/delete of the benchmark binary with malloc/free plus,
// inside a window, a count of the heap's growth (malloc_usable_size, so sized and unsized
// deletes agree). A block freed inside the window counts whenever it was allocated: the
// figure is how far the heap grew above where it stood when the window opened.
#include "bench/alloc_counter.h"

#include <malloc.h>
#include <sys/resource.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <new>

namespace wg::bench {
namespace {

std::atomic<bool> gCounting{false};
std::atomic<int64_t> gGrowth{0};
std::atomic<int64_t> gPeak{0};

void counted(void* p) {
  if (!p || !gCounting.load(std::memory_order_relaxed)) return;
  auto bytes = static_cast<int64_t>(malloc_usable_size(p));
  int64_t now = gGrowth.fetch_add(bytes, std::memory_order_relaxed) + bytes;
  int64_t peak = gPeak.load(std::memory_order_relaxed);
  while (now > peak && !gPeak.compare_exchange_weak(peak, now, std::memory_order_relaxed)) {
  }
}

void* allocate(size_t n) {
  void* p = std::malloc(n ? n : 1);
  if (!p) throw std::bad_alloc();
  counted(p);
  return p;
}

void* allocateAligned(size_t n, std::align_val_t a) {
  size_t align = static_cast<size_t>(a);
  void* p = std::aligned_alloc(align, (n + align - 1) / align * align);
  if (!p) throw std::bad_alloc();
  counted(p);
  return p;
}

void* allocateNoThrow(size_t n) noexcept {
  void* p = std::malloc(n ? n : 1);
  counted(p);
  return p;
}

void release(void* p) noexcept {
  if (!p) return;
  if (gCounting.load(std::memory_order_relaxed))
    gGrowth.fetch_sub(static_cast<int64_t>(malloc_usable_size(p)), std::memory_order_relaxed);
  std::free(p);
}

}  // namespace

void startHeapWindow() {
  gGrowth.store(0, std::memory_order_relaxed);
  gPeak.store(0, std::memory_order_relaxed);
  gCounting.store(true, std::memory_order_seq_cst);
}

size_t stopHeapWindow() {
  gCounting.store(false, std::memory_order_seq_cst);
  return static_cast<size_t>(gPeak.load(std::memory_order_relaxed));
}

size_t maxResidentBytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<size_t>(u.ru_maxrss) * 1024u;  // Linux reports KiB
}

}  // namespace wg::bench

void* operator new(size_t n) { return wg::bench::allocate(n); }
void* operator new[](size_t n) { return wg::bench::allocate(n); }
void* operator new(size_t n, const std::nothrow_t&) noexcept { return wg::bench::allocateNoThrow(n); }
void* operator new[](size_t n, const std::nothrow_t&) noexcept { return wg::bench::allocateNoThrow(n); }
void* operator new(size_t n, std::align_val_t a) { return wg::bench::allocateAligned(n, a); }
void* operator new[](size_t n, std::align_val_t a) { return wg::bench::allocateAligned(n, a); }
void operator delete(void* p) noexcept { wg::bench::release(p); }
void operator delete[](void* p) noexcept { wg::bench::release(p); }
void operator delete(void* p, size_t) noexcept { wg::bench::release(p); }
void operator delete[](void* p, size_t) noexcept { wg::bench::release(p); }
void operator delete(void* p, std::align_val_t) noexcept { wg::bench::release(p); }
void operator delete[](void* p, std::align_val_t) noexcept { wg::bench::release(p); }
void operator delete(void* p, size_t, std::align_val_t) noexcept { wg::bench::release(p); }
void operator delete[](void* p, size_t, std::align_val_t) noexcept { wg::bench::release(p); }
