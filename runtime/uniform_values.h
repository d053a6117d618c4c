#pragma once
// The values of the water's uniforms, the same for every backend: a builtin recomputed
// from the frame's camera, time and sun, or a graph parameter clamped into its manifest
// range. The GL renderer uploads them with glUniform*, the Vulkan renderer writes them
// into the std140 block (codegen/uniform_block_layout.h).
#include <cmath>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "core/interface_tables.h"
#include "runtime/scene.h"

namespace wg::rt {

struct FrameValues {
  Camera camera;
  glm::mat4 view{1.0f}, projection{1.0f}, viewProjection{1.0f};  // as the shaders get them
  glm::vec3 sun{0.0f, 1.0f, 0.0f};
  double time = 0;  // seconds: the phases take it in double; u_time is its float
  int width = 1, height = 1;
};

// Column-major matrices; empty for a builtin only `watergraph probe` sets (per case).
std::vector<float> builtinUniformValue(BuiltinUniform builtin, double angularFrequency, const FrameValues& frame);

// Into [lo, hi] per component; NaN becomes lo (or hi when lo is unbounded): the generated
// shader may rely on the range (codegen/value_facts.h).
template <class T>
T clampedIntoRange(T x, T lo, T hi) {
  if (!(x >= lo)) x = std::isfinite(lo) ? lo : (std::isfinite(hi) ? hi : x);
  return x > hi ? hi : x;
}
void clampIntoRange(std::vector<float>& value, float lo, float hi);

}  // namespace wg::rt
