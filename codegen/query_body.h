#pragma once
// What the C header and the JavaScript module of a surface query share: the statements
// of wg_<graph>_surface_at, which evaluates the displaced point and its derivatives along
// x0, z0 and t from the clamped parameters, written once for each language by
// codegen/query_ops.h.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "codegen/c_parameters.h"
#include "codegen/query_ops.h"
#include "core/diagnostic.h"
#include "core/program.h"

namespace wg {

struct QueryBody {
  std::string statements;             // indented by two spaces, one `const` local per line
  std::array<QueryScalar, 3> position;  // the displaced point's components
  std::vector<ProgramParameter> parameters;  // the graph's non-static parameters, in order
  std::vector<std::string> members;          // their member names (cIdentifier)
  bool readsParameters = false;
  // The spectral ocean the body reads through the state `o` (codegen/query_ocean.h), or nullptr.
  const ocean::OceanSettings* ocean = nullptr;
};

// The body for `language`: parameters are read from `p` (C: "p->m[1]", JavaScript:
// "p.m[1]") and clamped into their ranges; the point is x0, z0, the time t; a spectral
// ocean's maps and camera are read from the state `o`, whose functions start with `prefix`.
// nullopt with WG044 errors naming each node the query cannot evaluate.
std::optional<QueryBody> queryBody(const Program& program, HeaderLanguage language, const std::string& prefix,
                                   Diagnostics& diags);

}  // namespace wg
