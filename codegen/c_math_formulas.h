#pragma once
// The double formulas of the component-wise math nodes as C, and the `static` helpers
// (wgd_*) they call, for the generated surface query (codegen/query_ops.h writes the same
// formulas in C and, over the JavaScript twins of the helpers, in JavaScript). The C here
// follows each node's eval exactly (the same guards and constants, nodes/eval_math.h), so
// a query agrees with the CPU backend to rounding.
#include <string_view>

namespace wg {

// A component-wise node type's formula over the scalars $0, $1, $2 (its inputs' components)
// as a C expression over the wgd_ helpers and <math.h>; nullptr for another type.
const char* componentWiseFormula(std::string_view type);

// The `static` C helper functions the formulas call (wgd_*), each mirroring the node
// library's double form, NaN handling included.
std::string_view cMathHelpers();

}  // namespace wg
