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

// The CRC-32 a PNG chunk carries, over `count` bytes (its type and data).
unsigned long pngChunkCrc(const unsigned char* bytes, std::size_t count);

// "" when the chunks of the whole file `bytes` each fit inside it and carry a correct CRC,
// up to IEND; else which chunk declares more bytes than the file has, or has a wrong CRC. A 71-byte file whose IDAT declares 1.9 GB
// would otherwise make the decoder grow its buffer towards that size before it finds out.
std::string checkPngChunks(const unsigned char* bytes, std::size_t count);

}  // namespace wg
