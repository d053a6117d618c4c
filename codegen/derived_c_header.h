#pragma once
// `watergraph compile --target c-header`: a dependency-free C header that computes a
// graph's derived uniforms (codegen/derived_program.h) the way the runtime does, for an
// application that draws the generated shaders with its own renderer. It declares the
// graph's parameters and the per-draw values as plain structs of doubles, and one function
// that clamps the parameters into their ranges (as the runtime does), evaluates every
// derived program in double and rounds each result to the float the shader reads.
#include <string>
#include <vector>

#include "codegen/derived_program.h"

namespace wg {

struct DerivedUniform {
  std::string uniform;  // the name the shader declares: "u_derived0"
  DerivedValue value;
};

// The header's text. `parameters` are the graph's (the program's) parameters; each derived
// program reads them by index. Deterministic; throws std::logic_error for a program holding
// a node type outside derivedNodeTypes() (the planner never makes one).
std::string derivedCHeader(const std::string& graphName, const std::vector<ProgramParameter>& parameters,
                           const std::vector<DerivedUniform>& derived);

// The C identifier a graph name becomes in the header's names: "wg_<name>_" with every
// character outside [A-Za-z0-9_] replaced by '_'.
std::string derivedCPrefix(const std::string& graphName);

}  // namespace wg
