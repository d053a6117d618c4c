#pragma once
// The texture picker's model: the PNG files a graph may name (those under its folder that
// the loader accepts, core/texture_check.h), and choosing one for a node's texture option.
// The value saved is the path the graph format uses: relative to the graph's folder, with
// '/' separators ("textures/ripples.png"), or a "builtin:" name.
#include <string>
#include <vector>

#include "core/graph_edit.h"
#include "core/registry.h"

namespace wg::editor {

// How far the listing looks: folders below the graph's, and files in all. A larger tree is
// listed up to the limit (the picker says so); a path can still be typed.
inline constexpr int kTextureListDepth = 6;
inline constexpr size_t kTextureListLimit = 1000;

struct TextureChoices {
  std::vector<std::string> paths;  // sorted, each accepted by checkTextureSource
  bool truncated = false;          // more PNG files than kTextureListLimit
};

// The PNG files under `graphDir` ("" : the working folder) that a graph there may name;
// hidden folders (".git") are skipped, symbolic links are listed only where their target
// stays inside the folder, as the loader requires.
TextureChoices listGraphTextures(const std::string& graphDir);

// Sets texture option `option` of node `node` to `source` (one undo step), refused as the
// loader refuses it: outside the graph's folder, absolute, not a PNG, too large, not there.
std::string chooseTexture(GraphEditor& editor, const Registry& registry, const std::string& graphDir,
                          const std::string& node, const std::string& option, const std::string& source);

}  // namespace wg::editor
