// libFuzzer target: an `expression` node's formula, through the parser, the type rules,
// the lowering to math-node ops and the whole pipeline with glslang (formula_property.h).
// The dictionary (scripts/fuzz.sh) holds the language's function names and operators.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "formula_property.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  std::atexit(wg::fuzz::printPipelineStats);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string failed = wg::fuzz::formulaProperty({reinterpret_cast<const char*>(data), size});
  if (!failed.empty()) {
    std::fprintf(stderr, "watergraph formula property failed: %s\n", failed.c_str());
    std::abort();
  }
  return 0;
}
