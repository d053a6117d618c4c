// libFuzzer target: texture inputs, the graph's folder and its files under an attacker's
// control (PNG headers and sizes, paths with control characters, symbolic links in and out
// of the folder); the property is texture_property.h's. Each run uses its own scratch
// folder under $TMPDIR.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>

#include "texture_property.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::filesystem::path root =
      std::filesystem::temp_directory_path() / ("wg_fuzz_texture_" + std::to_string(::getpid()));
  std::string failed = wg::fuzz::textureProperty({reinterpret_cast<const char*>(data), size}, root);
  if (!failed.empty()) {
    std::fprintf(stderr, "watergraph texture property failed: %s\n", failed.c_str());
    std::abort();
  }
  return 0;
}
