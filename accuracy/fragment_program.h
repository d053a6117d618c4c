#pragma once
// The fragment stage of a compiled program on its own, for comparing a drawn frame with
// the double reference pixel by pixel: only the ops the fragment shader runs, each value
// the vertex stage hands it through a varying turned into a parameter (set per pixel from
// what the GPU interpolated, read back), and the fragment colour as the only output. As
// parameters, the varyings are perturbed by the conditioning term (accuracy/error_bound.h)
// like every other float32 input of the shader.
#include <vector>

#include "core/program.h"

namespace wg::accuracy {

struct FragmentProgram {
  Program program;
  // Per entry of the source Program::varyings: the index of the parameter carrying it.
  std::vector<int> varyingParameters;
};

// Requires the stage pass to have run (Op::stage set) and a fragment colour output;
// throws std::invalid_argument without one.
FragmentProgram fragmentProgram(const Program& program);

}  // namespace wg::accuracy
