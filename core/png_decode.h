#pragma once
// Decoding the PNG files checkTextureSource resolved (stb_image): for the runtimes and the
// CPU reference (nodes/texture_source), and for the check itself, so a file whose header
// is right but whose pixels do not decode fails validate, not only render.
#include <string>
#include <vector>

namespace wg {

struct DecodedPng {
  int width = 0, height = 0;
  std::vector<unsigned char> rgba;  // RGBA8, bottom row first (GL's v = 0 is the picture's bottom)
};

// The texels of the PNG at `realPath` (already resolved inside the graph's folder); false
// with *error set when the file cannot be read or decoded.
bool decodePng(const std::string& realPath, DecodedPng* out, std::string* error);

// "" when the file decodes, else why not. A file that decoded is remembered by its path,
// inode, size and modification and change times, so validate and the editor, which check
// every texture on every compile, decode it once until it changes; a failure is not
// remembered (it may pass).
std::string checkPngDecodes(const std::string& realPath);

}  // namespace wg
