#pragma once
// Which texture sources a graph may name: a built-in procedural texture or a .png inside
// the graph's folder. Checked when the graph is resolved, so a bad path is an error on the
// node's option, not a failure later in the runtime.
//
// The graph file and its folder may be hostile: a path is refused if it holds a control
// character (a NUL would cut it short in the file system), if its real path (after every
// symbolic link) leaves the graph's folder, or if the PNG's header declares more than
// kMaxTextureSide texels on a side (a small file can declare a gigabyte of texels).
#include <string>
#include <string_view>
#include <vector>

namespace wg {

inline constexpr std::string_view kBuiltinTexturePrefix = "builtin:";
const std::vector<std::string>& builtinTextureNames();  // builtinTextureTable()'s names

// The largest PNG side accepted, and the texels all of one graph's PNG textures may have
// together (two textures of the largest size: 512 MiB as RGBA8).
inline constexpr long long kMaxTextureSide = 8192;
inline constexpr long long kMaxGraphTextureTexels = 2 * kMaxTextureSide * kMaxTextureSide;

// A PNG source that passed the checks.
struct TextureFile {
  std::string realPath;  // after every symbolic link; inside the graph's folder
  long long width = 0;
  long long height = 0;
};

// "" when `source` is acceptable, else why not: an unknown builtin, a control character,
// an absolute path, a path that leaves the graph's folder (by "..", or by a symbolic link),
// a file that is not there, not a PNG, or larger than the limit. For a PNG source that is
// acceptable, `*file` (when given) says where it really is and its size.
std::string checkTextureSource(std::string_view source, const std::string& graphDir, TextureFile* file = nullptr);

// Why a size declared in a PNG header is refused, or "".
std::string checkTextureSize(long long width, long long height);

}  // namespace wg
