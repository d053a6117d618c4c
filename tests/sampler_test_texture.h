#pragma once
// The small PNGs the texture_sample tests sample (tests/nodes, tests/accuracy): texels
// chosen so that hand-computed values of each wrap mode, filter, colour space and mip
// level are short sums. Written in GL's row order (row 0 is v = 0), flipped into the PNG's
// top-to-bottom rows as any PNG is read back.
#include <cstdint>
#include <string>
#include <vector>

#include <stb/stb_image_write.h>

#include "test_support.h"

namespace wg::test {

// A w x h RGBA PNG whose texel (x, y) (y = 0 at v = 0) is texel(x, y, channel).
template <class Texel>
std::string samplerTestPng(int w, int h, Texel texel) {
  std::vector<unsigned char> rows(static_cast<size_t>(w) * static_cast<size_t>(h) * 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 4; ++c)
        rows[(static_cast<size_t>(h - 1 - y) * static_cast<size_t>(w) + static_cast<size_t>(x)) * 4 +
             static_cast<size_t>(c)] = static_cast<unsigned char>(texel(x, y, c));
  std::string out;
  auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<size_t>(size));
  };
  stbi_write_png_to_func(append, &out, w, h, 4, rows.data(), w * 4);
  return out;
}

// The 4x4 texture of the hand-computed cases:
//   r = 16 x + 64 y          (a ramp: every bilinear blend is a short sum)
//   g = 255 in column 0, else 0   (sRGB decoding before filtering shows at once)
//   b = 64 (x mod 2) + 128 (y mod 2)  (each 2x2 block averages to 96: mip level 1 and 2)
//   a = 255 - 32 x           (never colour-decoded)
inline int rampTexel(int x, int y, int c) {
  switch (c) {
    case 0: return 16 * x + 64 * y;
    case 1: return x == 0 ? 255 : 0;
    case 2: return 64 * (x % 2) + 128 * (y % 2);
    default: return 255 - 32 * x;
  }
}
inline std::string rampPng() { return samplerTestPng(4, 4, rampTexel); }

// A 16x16 texture of scrambled but deterministic bytes, for the GPU comparison: every
// blend of neighbouring texels differs.
inline int scrambledTexel(int x, int y, int c) {
  unsigned h = static_cast<unsigned>(x) * 73856093u ^ static_cast<unsigned>(y) * 19349663u ^ static_cast<unsigned>(c) * 83492791u;
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  return static_cast<int>(h & 0xffu);
}
inline std::string scrambledPng() { return samplerTestPng(16, 16, scrambledTexel); }

}  // namespace wg::test
