#pragma once
// What an edit changed, so the editor does the least work that shows it: nothing for a
// moved node, a uniform update for a parameter value, a recompile for anything else.
#include <string>
#include <vector>

#include "core/graph.h"

namespace wg::editor {

struct GraphChange {
  bool structural = false;              // needs a recompile
  std::vector<std::string> parameters;  // otherwise: parameters whose default changed
};

GraphChange compareGraphs(const Graph& before, const Graph& after);

}  // namespace wg::editor
