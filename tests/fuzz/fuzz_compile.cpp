// libFuzzer target: the whole pipeline (load -> resolve -> passes -> emit -> glslang, every
// target). Property in fuzz_properties.h (pipelineProperty): a clear error, or GLSL that
// glslang accepts for every target. A failure aborts; libFuzzer records it as a crash.
// Inputs are named "fuzz.json" in the current folder (relative texture paths resolve there).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "fuzz_properties.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  std::atexit(wg::fuzz::printPipelineStats);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string failed = wg::fuzz::pipelineProperty({reinterpret_cast<const char*>(data), size});
  if (!failed.empty()) {
    std::fprintf(stderr, "watergraph pipeline property failed: %s\n", failed.c_str());
    std::abort();
  }
  return 0;
}
