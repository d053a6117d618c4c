#pragma once
// Surface queries (issue 42), first step: the part of a compiled Program that moves the
// water, taken out on its own. It is the cone of ops below the vertex position output: the
// ops the vertex shader runs to displace the undisplaced water point (x0, 0, z0) at time t,
// over the graph's parameters. codegen/query_header.h writes it as C or JavaScript.
//
// Only what a query can evaluate may be in the cone: the node types queryOpKnown() names,
// the world position, time and mesh normal builtins, parameters and constants, and one
// spectral ocean (ocean_spectrum, read by ocean_displacement, whose camera input is the
// ocean state's camera). Anything else (a texture, the camera, a node type without a query form, such as a simulation
// this generator does not know yet) is a WG044 error naming the node, so a graph whose
// displacement cannot be queried is refused rather than answered wrongly.
#include <optional>
#include <vector>

#include "core/diagnostic.h"
#include "core/ocean_settings.h"
#include "core/program.h"

namespace wg {

struct QueryProgram {
  // The cone's ops in topological order, renumbered from 0; parameters are the source
  // Program's (ops read them by the same index).
  Program program;
  // The displaced position (vec3): an op output, or the world position builtin for a
  // graph that does not displace its water.
  ValueRef position;
  // Per op: whether an op of the cone reads its output port p (only port 0 of
  // gerstner_waves is differentiated; its normal and frame are not, see query_ops.h).
  std::vector<std::vector<bool>> portsRead;
  // The spectral ocean the displacement reads (its ocean_spectrum's settings, owned by the
  // source Program), or nullptr: then the query needs no state (codegen/query_ocean.h).
  const ocean::OceanSettings* ocean = nullptr;
};

// The query of `program` (after the passes: the stage pass must have run), or nullopt with
// WG044 errors in `diags`, one per op the query cannot evaluate.
std::optional<QueryProgram> extractQuery(const Program& program, Diagnostics& diags);

}  // namespace wg
