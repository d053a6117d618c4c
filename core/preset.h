#pragma once
// Graph-level presets (docs/graph-format.md "presets"): a named set of parameter values
// and node options chosen at compile time, e.g. weather presets calm | moderate | choppy,
// or quality levels that set octave counts and search sizes.
#include <string_view>

#include "core/diagnostic.h"
#include "core/graph.h"

namespace wg {

// Makes the values of preset `name` the defaults of their parameters (the loader has
// checked that each names a parameter and fits its type and range). A name the graph does
// not define is WG052, listing the presets it has; the graph is then left unchanged.
// Its node options replace (or add to) the options written on those nodes, keeping the
// preset's positions, so a value the node's type refuses is reported in the preset.
bool applyPreset(Graph& graph, std::string_view name, Diagnostics& diags);

// Writes `preset`'s values into `graph` (parameters' defaults, nodes' options); what names
// nothing in the graph is skipped (the loader has reported it).
void writePresetInto(Graph& graph, const Preset& preset);

}  // namespace wg
