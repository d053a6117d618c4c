#pragma once
// Shared by the voronoi and voronoi_caustics nodes: their `search`, `animation` and
// `speed` options and the orbit phase they turn into (a time-phase uniform, a wrapped
// time input, or 0), as GLSL and in double.
#include <string>
#include <vector>

#include "core/emit_context.h"
#include "core/node_spec.h"

namespace wg::nodes {

enum class VoronoiAnimation { Static, Time, TimeInput };

// The options, parsed once.
struct VoronoiOptions {
  bool fullSearch;  // 3x3 cells rather than 2x2
  VoronoiAnimation animation;
  double speed;  // rad/s
  bool animated() const { return animation != VoronoiAnimation::Static; }
};

// The options, with `speed` defaulting to defaultSpeed rad/s.
std::vector<OptionSpec> voronoiOptions(double defaultSpeed);
VoronoiOptions parseVoronoiOptions(const OptionReader& o);
// The phase for an orbit at speedScale times the `speed` option, in [0, 2 pi).
GlslExpr emitVoronoiPhase(EmitContext& ctx, const VoronoiOptions& o, double speedScale);
double evalVoronoiPhase(EvalContext& ctx, const VoronoiOptions& o, double speedScale);

}  // namespace wg::nodes
