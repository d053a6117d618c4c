#pragma once
// Graph-level presets (docs/graph-format.md "presets"): a named set of parameter values
// chosen at compile time, e.g. seed 004's weather presets calm | moderate | choppy.
#include <string_view>

#include "core/diagnostic.h"
#include "core/graph.h"

namespace wg {

// Makes the values of preset `name` the defaults of their parameters (the loader has
// checked that each names a parameter and fits its type and range). A name the graph does
// not define is WG052, listing the presets it has; the graph is then left unchanged.
bool applyPreset(Graph& graph, std::string_view name, Diagnostics& diags);

}  // namespace wg
