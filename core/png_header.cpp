#include "core/png_header.h"

#include <array>

namespace wg {
namespace {

unsigned long bigEndian32(const unsigned char* p) {
  return (static_cast<unsigned long>(p[0]) << 24) | (static_cast<unsigned long>(p[1]) << 16) |
         (static_cast<unsigned long>(p[2]) << 8) | static_cast<unsigned long>(p[3]);
}

}  // namespace

// The CRC-32 of PNG chunks (the PNG specification, annex D: polynomial 0xedb88320, reflected).
unsigned long pngChunkCrc(const unsigned char* bytes, std::size_t count) {
  static const auto table = [] {
    std::array<unsigned long, 256> t{};
    for (unsigned long n = 0; n < 256; ++n) {
      unsigned long c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xedb88320UL ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  unsigned long c = 0xffffffffUL;
  for (std::size_t i = 0; i < count; ++i) c = table[(c ^ bytes[i]) & 0xff] ^ (c >> 8);
  return c ^ 0xffffffffUL;
}

std::string readPngSize(const unsigned char* bytes, std::size_t count, PngSize* size) {
  static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (count < kPngHeaderBytes) return "it is not a PNG file (too short)";
  for (int i = 0; i < 8; ++i)
    if (bytes[i] != kSignature[i]) return "it is not a PNG file (no PNG signature)";
  if (bigEndian32(bytes + 8) != 13 || bytes[12] != 'I' || bytes[13] != 'H' || bytes[14] != 'D' || bytes[15] != 'R')
    return "it is not a PNG file (no IHDR chunk first)";
  size->width = static_cast<long long>(bigEndian32(bytes + 16));
  size->height = static_cast<long long>(bigEndian32(bytes + 20));
  if (size->width == 0 || size->height == 0) return "its PNG header declares an empty image";
  return "";
}

std::string checkPngChunks(const unsigned char* bytes, std::size_t count) {
  std::size_t at = 8;  // after the signature
  while (at < count) {
    if (count - at < 12) return "it ends inside a chunk's header at byte " + std::to_string(at);
    unsigned long length = bigEndian32(bytes + at);
    std::string type(reinterpret_cast<const char*>(bytes + at + 4), 4);
    for (char& c : type)
      if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'))) c = '?';
    // Chunk lengths are at most 2^31 - 1 (the PNG specification, 5.3).
    if (length > 0x7fffffffUL || length > count - at - 12)
      return "its " + type + " chunk at byte " + std::to_string(at) + " declares " + std::to_string(length) +
             " bytes of data; the file has " + std::to_string(count) + " bytes";
    // stb_image does not check CRCs: a corrupt chunk would decode into wrong texels.
    if (pngChunkCrc(bytes + at + 4, 4 + length) != bigEndian32(bytes + at + 8 + length))
      return "its " + type + " chunk at byte " + std::to_string(at) + " has a wrong CRC (the file is corrupt)";
    if (type == "IEND") return "";
    at += 12 + length;
  }
  return "it has no IEND chunk";
}

}  // namespace wg
