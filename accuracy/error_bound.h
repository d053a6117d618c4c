#pragma once
// The error bound a probe holds float32 GPU results to (NodeSpec::tolerance and
// NodeSpec::conditionRoundings, docs/accuracy.md): per output component
//   |gpu - ref| <= tolerance * max(1, |ref|) + conditioning,
// where `conditioning` is measured on the double reference itself: every float32 input
// component x the probe shader computes with (graph parameters, and the builtins it reads
// as plain uniforms) is moved by roundings * 2^-24 * |x| either way, one at a time, and
// the larger move of the result per input is summed over the inputs; so is each float32
// intermediate a node names
// (nodes/rounded_intermediates.h: a wave's phase), moved by its own roundings. To first order this is
// roundings * 2^-24 * sum |df/dx| |x|, the formula's condition number times the rounding;
// at a singular point (the slope of a sqrt at 0) it stays finite and is what float32
// rounding of the inputs does there. Time phases are excluded: the runtime computes them
// in double, so they carry no float32 rounding.
#include <array>
#include <map>
#include <string>
#include <vector>

#include "core/program.h"

namespace wg::accuracy {

struct ErrorModel {
  double tolerance = 0;
  double roundings = 0;
};

// The model of a probe program: the largest tolerance and condition roundings of its ops
// (1e-6 and none for a program without ops).
ErrorModel programErrorModel(const Program& program);

// The conditioning term per output component of `program`'s first output, perturbing the
// parameters and the builtin uniforms in `builtins` (UniformInfo::builtin of the shader's
// non-parameter uniforms). Zero when roundings is 0.
// `fetches`: node texture look-ups taken as given (codegen/cpu_backend.h), each value
// perturbed like a parameter (a float32 input of the shader's arithmetic).
// `filterPrecision`: each look-up the reference filters itself (one a library function
// makes, which cannot be read back) also moves by its filterUncertainty, one at a time:
// the GPU's subtexel precision, which `check` meets where the shader samples a texture
// in a loop (a ray march through a height map).
std::array<double, 4> conditioningTerm(const Program& program, const EvalEnvironment& env,
                                       const std::vector<Value>& parameters, const std::vector<BuiltinUniform>& builtins,
                                       double roundings, const std::map<std::string, std::vector<Value>>* fetches = nullptr,
                                       bool filterPrecision = false);

}  // namespace wg::accuracy
