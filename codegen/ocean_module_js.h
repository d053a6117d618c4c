#pragma once
// The spectral oceans' module for the web clients (clients/three, clients/webgpu): `compile`
// writes <graph>.ocean.js beside the manifest of a graph that reads an ocean_spectrum when it
// writes a web target (es300 or wgsl), and each entry of the manifest's "oceans" names it
// ("module"). It holds what only the compiler knows, so that a client ports none of the C++
// maths: each cascade's initial amplitudes h0 recomputed bit for bit by the query's own
// generator (codegen/query_ocean.h), packed as the runtime uploads them (h0(k) and
// conj(h0(-k)) in float32), the bins' frequency indices, the transform's twiddles, the
// 32-bit time phase, u_dk, and the foam's step constants and clock (core/ocean_foam.h).
// The simulation passes' shaders come with the scene description (`watergraph scene`).
#include <string>
#include <vector>

#include "codegen/shader_plan.h"
#include "core/program.h"

namespace wg {

// "<graph>.ocean.js".
std::string oceanModuleFileName(const std::string& graphBase);

// The module's text for `oceans` (the manifest's, in its order), whose settings are those of
// `program`'s ocean_spectrum ops of the same node ids.
std::string oceanModuleJs(const std::string& graphName, const Program& program, const std::vector<OceanInfo>& oceans);

}  // namespace wg
