// libFuzzer target: the graph loader (JSON with positions -> Graph). Properties in
// fuzz_properties.h (loaderProperty); a failure aborts, which libFuzzer records as a crash.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "fuzz_properties.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string failed = wg::fuzz::loaderProperty({reinterpret_cast<const char*>(data), size});
  if (!failed.empty()) {
    std::fprintf(stderr, "watergraph loader property failed: %s\n", failed.c_str());
    std::abort();
  }
  return 0;
}
