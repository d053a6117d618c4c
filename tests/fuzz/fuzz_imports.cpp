// libFuzzer target: graphs that import graphs. The input is up to six graph files
// separated by NUL bytes (top.json, lib/f1.json, ...); property in imports_property.h.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "imports_property.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string dir =
      (std::filesystem::temp_directory_path() / ("wg_fuzz_imports_" + std::to_string(::getpid()))).string();
  std::string failed = wg::fuzz::importsProperty({reinterpret_cast<const char*>(data), size}, dir);
  if (!failed.empty()) {
    std::fprintf(stderr, "watergraph imports property failed: %s\n", failed.c_str());
    std::abort();
  }
  return 0;
}
