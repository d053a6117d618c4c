#pragma once
// Saving a layout change (nodes moved on the canvas, frames made or edited, nothing else)
// into the file as it was written: only the nodes' "editor": {"x", "y"} values and the
// graph's "editor" value (its frames) change, so a hand-formatted file is not reformatted
// to the canonical form by dragging a node or naming a frame. Anything more than the
// layout, or a file already canonical, is saved canonically as before.
#include <optional>
#include <string>

#include "core/graph.h"

namespace wg::editor {

// `onDisk` is `diskText` parsed (positions of nodes without one filled in by the layout);
// `edited` the graph to save. The text with the layout of `edited` written into
// `diskText`, or empty when `edited` differs from `onDisk` in more than its layout or
// the text cannot be patched so that it reads back as `edited` (then save canonically).
std::optional<std::string> patchLayoutOnly(const std::string& diskText, const Graph& onDisk, const Graph& edited);

}  // namespace wg::editor
