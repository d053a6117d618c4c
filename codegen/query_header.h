#pragma once
// `watergraph compile --target query-c` and `--target query-js`: the graph's vertex-stage
// displacement (codegen/query_program.h) as a dependency-free C header (C99, also C++)
// and as a JavaScript ES module with the same API (docs/queries.md):
//   wg_<graph>_params, wg_<graph>_params_default(p)
//   wg_<graph>_displace(p, x0, z0, t, position[3], normal[3], velocity[3])
//   wg_<graph>_height(p, x, z, t)
//   wg_<graph>_displace_batch / wg_<graph>_height_batch (many points at one time)
// <graph> is cIdentifier(graph name) (codegen/c_names.h). No allocation, no state: safe
// to call from any number of threads.
#include <optional>
#include <string>

#include "core/diagnostic.h"
#include "core/program.h"

namespace wg {

// The Newton iteration of height(): it stops when the displaced point is within
// kQueryHeightTolerance * (1 + |x| + |z|) metres of (x, z) in x and in z, or after
// kQueryMaxSteps evaluations (then the best point found answers).
inline constexpr double kQueryHeightTolerance = 1e-13;
inline constexpr int kQueryMaxSteps = 64;

// The header's or module's text, or nullopt with WG044 errors naming each node the query
// cannot evaluate. `program` is the compiled Program (after the passes).
std::optional<std::string> queryCHeader(const std::string& graphName, const Program& program, Diagnostics& diags);
std::optional<std::string> queryJsModule(const std::string& graphName, const Program& program, Diagnostics& diags);

}  // namespace wg
