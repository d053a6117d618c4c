#include "runtime/tessellation_budget.h"

#include <algorithm>
#include <cmath>

namespace wg::rt {

std::int64_t tessellatedTriangles(int quadsPerSide, double factor) {
  double level = std::clamp(std::isfinite(factor) ? std::ceil(factor) : 64.0, 1.0, 64.0);  // GL's largest level is 64
  double patches = 2.0 * quadsPerSide * quadsPerSide;
  return static_cast<std::int64_t>(std::ceil(patches * 1.5 * level * level));
}

int tessellatedGridQuads(int requested, double factor) {
  int quads = std::max(requested, 1);
  while (quads > 1 && tessellatedTriangles(quads, factor) > kMaxTessellatedTrianglesPerDraw) --quads;
  return quads;
}

}  // namespace wg::rt
