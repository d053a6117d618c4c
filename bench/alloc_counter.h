#pragma once
// A counting global allocator for the benchmarks (alloc_counter.cpp replaces operator
// new/delete in the benchmark binaries only). Counting is on only inside a window, so the
// timed loops pay one relaxed atomic load per allocation and nothing else.
#include <cstddef>

namespace wg::bench {

// Starts counting: heap bytes allocated minus bytes freed from now on, and their peak.
void startHeapWindow();
// Stops counting; returns the peak growth of the heap since startHeapWindow, in bytes.
size_t stopHeapWindow();

// The process's peak resident set (getrusage ru_maxrss), in bytes.
size_t maxResidentBytes();

}  // namespace wg::bench
