#pragma once
// A screen-sized scene texture (scene depth, scene colour, a planar pass) as the GPU
// passes rendered it, for the CPU reference to sample where a shader samples it at
// positions of its own choosing: an SSR march, a refracted look-up. `check` reads them
// back for deferred water (accuracy/readback.h); everywhere else the reference sees one
// value per texture and pixel (EvalEnvironment's fields).
//
// Sampling follows GL's rules with integer texel coordinates (OpenGL 4.6 core §8.14, as
// nodes/texture_sampling.h) for the state the runtime gives scene targets: clamp to edge,
// and nearest (depth, the G-buffer) or linear (colour) filtering, all in double.
#include <vector>

#include "core/value.h"

namespace wg {

struct SceneImage {
  int width = 0, height = 0;
  int channels = 0;            // 1 (a depth) or 3 (a colour)
  std::vector<float> texels;   // [(j * width + i) * channels + c], row j = 0 at the bottom (t = 0)
  bool nearest = false;        // GL_NEAREST, else GL_LINEAR

  float texel(int i, int j, int c) const {
    return texels[(static_cast<size_t>(j) * static_cast<size_t>(width) + static_cast<size_t>(i)) * channels + c];
  }
  // What texture(sampler, vec2(u, v)) returns: a float for a depth, a vec3 for a colour.
  // A non-finite coordinate reads at 0, as the node texture sampler does.
  Value sample(double u, double v) const;
};

}  // namespace wg
