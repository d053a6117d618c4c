#pragma once
// The node types a derived uniform's program may hold, and each one's formula as C.
// A derived uniform is computed outside the shader: by the runtimes with the double CPU
// backend (the nodes' own evals), by the three.js client (clients/three/watergraph-derived.js)
// and by the C header `compile --target c-header` writes. So a node type is allowed in a
// derived program only where all three exist; a per-draw candidate holding any other type
// stays in the shader. The C here follows each node's eval exactly (the same guards and
// constants, nodes/eval_math.h), and tests/codegen/derived_c_header_test.cpp holds the two
// to each other.
#include <string>
#include <string_view>
#include <vector>

#include "core/program.h"

namespace wg {

// In name order.
const std::vector<std::string_view>& derivedNodeTypes();
bool isDerivedNodeType(std::string_view type);

// C statements that compute `op`'s outputs: `inputs[i]` names a `const double*` holding
// input i's source value, of type `sourceTypes[i]` (a float splats over the port's
// components, as the CPU backend converts it), `outputs[p]` a `double[]` for output p.
// Uses the helpers of derivedCHelpers(). Throws std::logic_error for a type outside the
// vocabulary.
std::string derivedOpC(const Op& op, const std::vector<std::string>& inputs, const std::vector<Type>& sourceTypes,
                       const std::vector<std::string>& outputs);

// A component-wise node type's formula over the scalars $0, $1, $2 (its inputs' components)
// as a C expression over the wgd_ helpers and <math.h>; nullptr for another type. The
// surface query (codegen/query_ops.h) writes the same formulas, in C and JavaScript.
const char* componentWiseFormula(std::string_view type);

// The `static` C helper functions the statements call (wgd_*), each mirroring the node
// library's double form, NaN handling included.
std::string_view derivedCHelpers();

}  // namespace wg
