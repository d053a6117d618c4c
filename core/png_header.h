#pragma once
// The size a PNG declares in its header, read before anything is decoded: a 260 KB file can
// declare 16384 x 16384 texels (a gigabyte once decoded), so the size is checked first.
#include <cstddef>
#include <string>

namespace wg {

// Bytes a PNG needs for its size: the 8-byte signature and the IHDR chunk's length, type,
// width and height.
inline constexpr std::size_t kPngHeaderBytes = 24;

struct PngSize {
  long long width = 0;
  long long height = 0;
};

// "" and *size set when `bytes` start like a PNG (signature, then an IHDR chunk of 13
// bytes); else why not.
std::string readPngSize(const unsigned char* bytes, std::size_t count, PngSize* size);

}  // namespace wg
