// libFuzzer target: sequences of edit-model operations (core/graph_edit.h) with hostile
// arguments, chosen by the bytes; whatever the editor accepts must save and load back equal
// (edit_sequence.h, the property tests/core/graph_edit_property_test.cpp also runs).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "edit_sequence.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string failed = wg::fuzz::editSequenceProperty({reinterpret_cast<const char*>(data), size});
  if (!failed.empty()) {
    std::fprintf(stderr, "watergraph edit-sequence property failed: %s\n", failed.c_str());
    std::abort();
  }
  return 0;
}
