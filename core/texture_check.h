#pragma once
// Which texture sources a graph may name: a built-in procedural texture or a .png inside
// the graph's folder. Checked when the graph is resolved, so a bad path is an error on the
// node's option, not a failure later in the runtime.
#include <string>
#include <string_view>
#include <vector>

namespace wg {

inline constexpr std::string_view kBuiltinTexturePrefix = "builtin:";
const std::vector<std::string>& builtinTextureNames();  // builtinTextureTable()'s names

// "" when `source` is acceptable, else why not: an unknown builtin, an absolute path, a
// path that leaves the graph's folder, a file that is not there or not a .png.
std::string checkTextureSource(std::string_view source, const std::string& graphDir);

}  // namespace wg
