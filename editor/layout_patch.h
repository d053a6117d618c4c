#pragma once
// Saving a layout change (nodes moved on the canvas, nothing else) into the file as it was
// written: only the nodes' "editor": {"x", "y"} values change, so a hand-formatted file is
// not reformatted to the canonical form by dragging a node. Anything more than positions,
// or a file already canonical, is saved canonically as before.
#include <optional>
#include <string>

#include "core/graph.h"

namespace wg::editor {

// `onDisk` is `diskText` parsed (positions of nodes without one filled in by the layout);
// `edited` the graph to save. The text with the positions of `edited` written into
// `diskText`, or empty when `edited` differs from `onDisk` in more than node positions or
// the text cannot be patched so that it reads back as `edited` (then save canonically).
std::optional<std::string> patchLayoutOnly(const std::string& diskText, const Graph& onDisk, const Graph& edited);

}  // namespace wg::editor
