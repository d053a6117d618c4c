#pragma once
// Float32 intermediates of a node that round on their own, which moving the node's inputs
// cannot stand for (accuracy/error_bound.h adds them to the conditioning term). A sum of
// terms each computed from the inputs (a Gerstner wave's phase k D.x) rounds each term
// separately: their errors add where the exact terms' slopes cancel in the sum, so moving
// an input (which moves every term together) can show a far smaller move than float32
// makes. Kept beside NodeSpec, keyed by node type; it reads like a NodeSpec member and
// can move there.
#include <functional>
#include <memory>
#include <string_view>
#include <vector>

#include "core/node_options.h"

namespace wg::nodes {

// The options once per such intermediate, that intermediate scaled by (1 + relative).
using RoundedIntermediates =
    std::function<std::vector<std::shared_ptr<const ParsedOptions>>(const ParsedOptions& options, double relative)>;

// The node type's, or null when it has none.
const RoundedIntermediates* roundedIntermediates(std::string_view nodeType);

// gerstner_waves (nodes/gerstner_waves.cpp): each wave's direction components, one at a
// time, so its phase argument D.(x, z) moves by its own rounding.
std::vector<std::shared_ptr<const ParsedOptions>> gerstnerRoundedIntermediates(const ParsedOptions& options,
                                                                                double relative);

// voronoi_caustics (nodes/voronoi_caustics.cpp): the second layer's coordinate 1.3 q + 5.
std::vector<std::shared_ptr<const ParsedOptions>> voronoiCausticsRoundedIntermediates(const ParsedOptions& options,
                                                                                       double relative);

}  // namespace wg::nodes
