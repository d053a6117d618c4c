#pragma once
// `watergraph compile --target query-c` and `--target query-js`: the graph's vertex-stage
// displacement (codegen/query_program.h) as a dependency-free C header (C99, also C++)
// and as a JavaScript ES module with the same API (docs/queries.md):
//   wg_<graph>_params, wg_<graph>_params_default(p)
//   wg_<graph>_displace(p, x0, z0, t, position[3], normal[3], velocity[3])
//   wg_<graph>_height(p, x, z, t)
//   wg_<graph>_displace_batch / wg_<graph>_height_batch (many points at one time)
// <graph> is cIdentifier(graph name) (codegen/c_names.h). No allocation, no state: safe
// to call from any number of threads. A spectral ocean's maps are the exception: they live
// in a state the host owns (codegen/query_ocean.h), which displace and height take after the
// parameters, in place of t, and only read.
#include <optional>
#include <string>

#include "codegen/c_parameters.h"
#include "core/diagnostic.h"
#include "core/program.h"

namespace wg {

// The Newton iteration of height(): it stops when the displaced point is within
// kQueryHeightTolerance * (1 + |x| + |z|) metres of (x, z) in x and in z, or after
// kQueryMaxSteps evaluations (then the best point found answers).
inline constexpr double kQueryHeightTolerance = 1e-13;
inline constexpr int kQueryMaxSteps = 128;
// A step that does not bring the point closer is halved, at most this many times in a row;
// then the steps are stuck where the residual has a minimum that is no root (beside a fold
// of the surface) and start again from the next point of queryRestartTable.
inline constexpr int kQueryHalvings = 3;

// The declaration of `restart`, eight (direction x, direction z, fraction of the reach)
// triples: where height() starts again around (x, z), at the largest horizontal
// displacement seen so far times the fraction (a root lies within the displacement's reach
// of (x, z): x0 -> (x, z) - D(x0).xz maps that disk into itself), the fraction times 1,
// 0.7, 0.4 in turn on each pass through the eight. Literals, not trigonometry, so the C header and the JavaScript module start
// again from the same points to the last bit.
std::string queryRestartTable(HeaderLanguage language);

// The header's or module's text, or nullopt with WG044 errors naming each node the query
// cannot evaluate. `program` is the compiled Program (after the passes).
std::optional<std::string> queryCHeader(const std::string& graphName, const Program& program, Diagnostics& diags);
// The <math.h> names and the wgd_/wgq_ helpers the JavaScript query's expressions call,
// each as its C form computes it (const declarations at a module's top level).
std::string queryJsMathHelpers();
std::optional<std::string> queryJsModule(const std::string& graphName, const Program& program, Diagnostics& diags);

}  // namespace wg
