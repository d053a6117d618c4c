#pragma once
// The error panel's lines: each diagnostic with the file it is in (an error inside a
// subgraph is in the subgraph's file, with a note per instance it was reached through),
// and the node of the open graph that clicking it selects.
#include <string>

#include "core/diagnostic.h"
#include "core/graph.h"

namespace wg::editor {

// formatText's line, with the paths of files inside `folder` (the top-level graph's, where
// every import lies) written relative to it: `lib/tint.json:9:5: error: ...`.
std::string errorListText(const Diagnostic& d, const std::string& folder);

// The node of `open` the diagnostic is about: its node, or for one inside a subgraph (in
// the subgraph's file, or named "water/scaled") the instance it lies in ("water"); ""
// when none is in `open`.
std::string nodeToSelect(const Diagnostic& d, const Graph& open);

}  // namespace wg::editor
