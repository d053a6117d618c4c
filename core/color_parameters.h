#pragma once
// Colour-managed values (docs/graph-format.md, "Colour"): a parameter with the hint
// "color" or "hdr_color", a literal given to a colour port (PortSpec::color) and such a
// port's default are authored as the sRGB values a colour picker shows. Every node works in
// linear values, so resolve linearises them when the graph is compiled:
//   - a colour parameter's reads all go through one srgb_to_linear op (the parameter keeps
//     its sRGB value: the uniform a host sets, the manifest's default and range), which
//     constant folding turns into linear constants for a static parameter;
//   - a colour literal or default becomes its linear value, computed here in double.
// Data (a direction, a mask, coefficients: a parameter without a hint, a port without the
// flag) is never converted.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/graph.h"
#include "core/program.h"
#include "core/registry.h"

namespace wg {

// The hints that make a parameter an sRGB-authored colour.
inline constexpr std::string_view kColorHint = "color";        // components within [0, 1]
inline constexpr std::string_view kHdrColorHint = "hdr_color";  // components may exceed 1
// The node type resolve inserts after every read of a colour parameter.
inline constexpr std::string_view kLinearisationNode = "srgb_to_linear";

bool isColorHint(std::string_view hint);
// The colour space a parameter's values are authored in, as the manifest states it:
// "srgb" for a colour parameter, "" for data.
std::string_view parameterColorSpace(std::string_view hint);

// Why values `xs` do not suit a parameter with hint `hint` (`label` names them), or
// nothing: a "color" parameter's default, range and preset values lie within [0, 1].
std::optional<std::string> colorRangeProblem(std::string_view hint, const std::vector<double>& xs,
                                             const std::string& label);

// A literal or default of a colour port, in linear terms (core/color_space.h).
Value linearColor(const Value& srgb);

// Appends to `program` the op that linearises parameter `param` (a colour parameter) and
// returns its output: what every read of the parameter becomes. The op is named
// "$<parameter>" in the manifest's node lists.
ValueRef appendParameterLinearisation(Program& program, const Registry& registry, int param);
// Whether an op with this node id is such a linearisation (no graph node: ids are identifiers).
inline bool isParameterLinearisation(std::string_view nodeId) { return !nodeId.empty() && nodeId.front() == '$'; }

}  // namespace wg
