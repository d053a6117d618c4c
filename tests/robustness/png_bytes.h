#pragma once
// A valid w x h RGBA PNG, every byte `value`, encoded in memory: for the texture tests that
// need real PNG bytes to corrupt or to size.
#include <string>
#include <vector>

#include <stb/stb_image_write.h>

namespace wg::test {

inline std::string pngBytes(int w, int h, unsigned char value = 200) {
  std::vector<unsigned char> rgba(static_cast<size_t>(w) * static_cast<size_t>(h) * 4, value);
  std::string out;
  auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<size_t>(size));
  };
  stbi_write_png_to_func(append, &out, w, h, 4, rgba.data(), w * 4);
  return out;
}

}  // namespace wg::test
