#pragma once
// The texture-input property, shared by the fuzz target (fuzz_texture.cpp) and the replay
// of its corpus in the test suite: the bytes build a graph folder (a PNG's header and data,
// a file name, symbolic links in and out of the folder) and name a texture path; the check
// (core/texture_check.h) and the decoder (nodes/texture_source.h) must then agree with the
// rules, whatever the bytes: a path with a control character, one that leaves the folder
// (after links) or a PNG over the size limit is refused, and a texture that loads has the
// size its header declared, within the limit.
#include <algorithm>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>
#include <unistd.h>

#include "core/png_header.h"
#include "core/texture_check.h"
#include "nodes/texture_source.h"

namespace wg::fuzz {

// "" when the property holds for `bytes`, using (and emptying) the scratch folder `root`.
inline std::string textureProperty(std::string_view bytes, const std::filesystem::path& root) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::remove_all(root, ec);
  fs::path dir = root / "graph", outside = root / "outside";
  fs::create_directories(dir / "sub", ec);
  fs::create_directories(outside, ec);
  if (ec) return "";  // the scratch folder is not usable: nothing to check
  // Layout: byte 0 chooses links; then the path up to the first '|'; the rest is the file.
  unsigned flags = bytes.empty() ? 0 : static_cast<unsigned char>(bytes[0]);
  std::string_view rest = bytes.empty() ? bytes : bytes.substr(1);
  std::size_t bar = rest.find('|');
  std::string path(rest.substr(0, std::min(bar, std::size_t{200})));
  std::string contents(bar == std::string_view::npos ? std::string_view() : rest.substr(bar + 1));
  // Every chunk's CRC is made right (a mutation would otherwise break one and the file be
  // refused before the decoder sees it): flag 16 leaves them as the bytes say.
  if (!(flags & 16)) {
    auto* u = reinterpret_cast<unsigned char*>(contents.data());
    for (std::size_t at = 8; at + 12 <= contents.size();) {
      std::size_t length = (std::size_t{u[at]} << 24) | (std::size_t{u[at + 1]} << 16) | (std::size_t{u[at + 2]} << 8) | u[at + 3];
      if (length > contents.size() - at - 12) break;
      unsigned long crc = pngChunkCrc(u + at + 4, 4 + length);
      for (int k = 0; k < 4; ++k) u[at + 8 + length + k] = static_cast<unsigned char>(crc >> (24 - 8 * k));
      at += 12 + length;
    }
  }
  auto write = [&](const fs::path& p) {
    std::FILE* f = std::fopen(p.c_str(), "wb");
    if (!f) return;
    std::fwrite(contents.data(), 1, contents.size(), f);
    std::fclose(f);
  };
  write(dir / "t.png");
  write(outside / "t.png");
  if (flags & 1) fs::create_symlink(outside / "t.png", dir / "out.png", ec);       // leads outside
  if (flags & 2) fs::create_directory_symlink(outside, dir / "ext", ec);           // folder leading outside
  if (flags & 4) fs::create_symlink("../t.png", dir / "sub" / "up.png", ec);       // stays inside
  if (flags & 8) fs::create_symlink(dir / "missing.png", dir / "dangling.png", ec);
  TextureFile file;
  std::string why = checkTextureSource(path, dir.string(), &file);
  bool builtin = path.rfind(kBuiltinTexturePrefix, 0) == 0;
  if (why.empty() && !builtin) {
    if (std::any_of(path.begin(), path.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; }))
      return "a path with a control character was accepted";
    fs::path real = fs::canonical(dir, ec);
    if (fs::path(file.realPath).lexically_relative(real).string().rfind("..", 0) == 0)
      return "a path leading outside the folder was accepted: " + file.realPath;
    if (file.width < 1 || file.height < 1 || file.width > kMaxTextureSide || file.height > kMaxTextureSide)
      return "a PNG of " + std::to_string(file.width) + " x " + std::to_string(file.height) + " was accepted";
  }
  std::string error;
  auto image = loadTexture(path, dir.string(), &error);
  if (image && !builtin) {
    if (!why.empty()) return "loadTexture decoded what the check refused: " + why;
    if (image->width != file.width || image->height != file.height) return "the decoded size is not the header's";
    if (image->rgba.size() != static_cast<std::size_t>(image->width) * static_cast<std::size_t>(image->height) * 4)
      return "the decoded image has the wrong number of bytes";
  }
  if (!image && error.empty()) return "loadTexture failed without saying why";
  return "";
}

}  // namespace wg::fuzz
