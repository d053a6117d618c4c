// libFuzzer target: a GLSL function file (a glsl_function node's .glsl), through the
// scan of its declarations, glslang's parse for every target, the renaming into the
// node's namespace and the whole pipeline (function_file_property.h). The corpus
// (tests/fuzz/corpus/function_file/) starts from small valid and faulty files.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <unistd.h>

#include "function_file_property.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::filesystem::path scratch =
      std::filesystem::temp_directory_path() / ("wg_fuzz_function_file_" + std::to_string(getpid()));
  std::string failed = wg::fuzz::functionFileProperty({reinterpret_cast<const char*>(data), size}, scratch);
  if (!failed.empty()) {
    std::fprintf(stderr, "watergraph function file property failed: %s\n", failed.c_str());
    std::abort();
  }
  return 0;
}
