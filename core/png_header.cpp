#include "core/png_header.h"

namespace wg {
namespace {

unsigned long bigEndian32(const unsigned char* p) {
  return (static_cast<unsigned long>(p[0]) << 24) | (static_cast<unsigned long>(p[1]) << 16) |
         (static_cast<unsigned long>(p[2]) << 8) | static_cast<unsigned long>(p[3]);
}

}  // namespace

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

}  // namespace wg
