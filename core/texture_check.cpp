#include "core/texture_check.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fcntl.h>
#include <unistd.h>

#include "core/png_header.h"

#include "core/interface_tables.h"

namespace wg {
namespace {

namespace fs = std::filesystem;

bool hasControlCharacter(std::string_view s) {
  return std::any_of(s.begin(), s.end(), [](char c) {
    auto u = static_cast<unsigned char>(c);
    return u < 0x20 || u == 0x7f;
  });
}

// `path` lies inside `folder` (both already free of symbolic links and "..").
bool isInside(const fs::path& path, const fs::path& folder) {
  fs::path rel = path.lexically_relative(folder);
  return !rel.empty() && *rel.begin() != ".." && rel != ".";
}

// The header's declared size, read from the file itself (O_NOFOLLOW: the path is already
// resolved, so a link planted since is refused rather than followed).
std::string readHeader(const fs::path& path, PngSize* size) {
  int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) return std::string("it cannot be opened: ") + std::strerror(errno);
  unsigned char bytes[kPngHeaderBytes];
  ssize_t n = ::read(fd, bytes, sizeof bytes);
  ::close(fd);
  if (n < 0) return std::string("it cannot be read: ") + std::strerror(errno);
  return readPngSize(bytes, static_cast<std::size_t>(n), size);
}

}  // namespace

const std::vector<std::string>& builtinTextureNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& row : builtinTextureTable()) n.emplace_back(row.name);
    return n;
  }();
  return names;
}

std::string checkTextureSize(long long width, long long height) {
  if (width > kMaxTextureSide || height > kMaxTextureSide)
    return "its PNG header declares " + std::to_string(width) + " x " + std::to_string(height) +
           " texels; the limit is " + std::to_string(kMaxTextureSide) + " on a side";
  return "";
}

std::string checkTextureSource(std::string_view source, const std::string& graphDir, TextureFile* file) {
  if (source.rfind(kBuiltinTexturePrefix, 0) == 0) {
    std::string name(source.substr(kBuiltinTexturePrefix.size()));
    const auto& names = builtinTextureNames();
    if (std::find(names.begin(), names.end(), name) != names.end()) return "";
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "builtin:" : ", builtin:") + n;
    return "unknown built-in texture '" + std::string(source) + "' (" + list + ")";
  }
  if (source.empty()) return "an empty texture path";
  const std::string quoted = "texture path '" + std::string(source) + "'";
  // Before anything reaches the file system: "README.md\0.png" would open README.md.
  if (hasControlCharacter(source)) return quoted + " contains a control character";
  fs::path rel(source);
  if (rel.is_absolute()) return quoted + " must be relative to the graph file";
  // "sub/../ok.png" stays inside; a ".." left after folding the steps does not (links are
  // followed below, and the real path must stay inside too).
  fs::path folded = rel.lexically_normal();
  if (!folded.empty() && *folded.begin() == "..") return quoted + " leaves the graph's folder";
  std::string extension = rel.extension().string();  // .png in any case: files saved as UP.PNG
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension != ".png") return "texture '" + std::string(source) + "' is not a .png file";
  fs::path folder(graphDir.empty() ? "." : graphDir);
  fs::path full = folder / rel;
  std::error_code ec;
  if (!fs::is_regular_file(full, ec))
    return "texture file '" + full.string() + (fs::exists(full, ec) ? "' is not a regular file" : "' does not exist");
  // Through every symbolic link, of the file and of each folder on the way.
  fs::path realFolder = fs::canonical(folder, ec);
  fs::path real = ec ? fs::path() : fs::canonical(full, ec);
  if (ec) return "texture file '" + full.string() + "' cannot be resolved: " + ec.message();
  if (!isInside(real, realFolder)) return quoted + " leads outside the graph's folder (through a symbolic link)";
  PngSize size;
  if (std::string why = readHeader(real, &size); !why.empty()) return "texture '" + std::string(source) + "': " + why;
  if (std::string why = checkTextureSize(size.width, size.height); !why.empty())
    return "texture '" + std::string(source) + "': " + why;
  if (file) *file = {real.string(), size.width, size.height};
  return "";
}

}  // namespace wg
