#include "core/texture_check.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "core/file_read.h"
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


// The header's declared size, read from the file itself: opened once, and where the open
// file really lies is checked again on its descriptor (core/file_read.h), so a file or a
// folder swapped for a link since the path was resolved is refused, never read. *real is
// the opened file's real path, which the decoder later insists on.
std::string readHeader(const fs::path& path, const fs::path& realFolder, PngSize* size, std::string* real) {
  FileReadRule rule;
  rule.maxBytes = static_cast<std::size_t>(-1);  // the decoder holds the size limit
  rule.insideFolder = realFolder.string();
  rule.readAtMost = kPngHeaderBytes;
  FileReadFailure failure;
  auto text = readFileChecked(path.string(), rule, &failure);
  if (!text) {
    if (failure.kind == FileReadFailure::Kind::Outside) return "it leads outside the graph's folder (it changed since it was checked)";
    return "it cannot be read: " + failure.why();
  }
  *real = text->realPath;
  return readPngSize(reinterpret_cast<const unsigned char*>(text->bytes.data()), text->bytes.size(), size);
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
  if (!pathLiesUnder(real.string(), realFolder.string())) return quoted + " leads outside the graph's folder (through a symbolic link)";
  PngSize size;
  std::string opened;
  if (std::string why = readHeader(full, realFolder, &size, &opened); !why.empty())
    return "texture '" + std::string(source) + "': " + why;
  if (std::string why = checkTextureSize(size.width, size.height); !why.empty())
    return "texture '" + std::string(source) + "': " + why;
  if (file) *file = {opened, size.width, size.height};
  return "";
}

}  // namespace wg
