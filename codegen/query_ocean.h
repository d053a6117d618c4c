#pragma once
// The spectral ocean in a surface query (docs/queries.md, "The spectral ocean"). The GPU
// keeps an ocean's cascades as maps it recomputes every frame; a query cannot hold those
// megabytes as tables in its text, so it recomputes them on the CPU, in double, into a state
// the host owns:
//   wg_<graph>_ocean                  a fixed-size struct (arrays sized by the cascades' N;
//                                     no allocation)
//   wg_<graph>_ocean_init(o)          each cascade's initial amplitudes h0(k), drawn from the
//                                     ocean_spectrum's spectrum with its counter-based
//                                     Gaussian numbers (core/ocean_random.h): the very h0 the
//                                     compiler uploads to the GPU, recomputed bit for bit
//   wg_<graph>_ocean_update(o, t, camera)
//                                     the spectra evolved to time t with the same 32-bit
//                                     phases as the GPU, and six packed inverse FFTs per
//                                     cascade (a radix-2 transform of the header's own) into
//                                     the maps; camera (may be NULL) is where the readers'
//                                     fade distances are measured from
//   wg_<graph>_ocean_sample(o, x, z, w, out)
//                                     the cascades' maps at the world point (x, z), bicubic
//                                     between the 4 x 4 texels around it as the vertex shader
//                                     reads them (wg_ocean_map_cubic), weighted by w and summed
// update writes the state; everything else only reads it.
#include <string>

#include "codegen/c_parameters.h"
#include "core/ocean_settings.h"

namespace wg {

// The channels of a texel of a query's ocean map, in order: the GPU's displacement map
// (lambda Dx, h, lambda Dz, lambda dDx/dz), its slope map (dh/dx, dh/dz, lambda dDx/dx,
// lambda dDz/dz), then the velocity d/dt (lambda Dx, h, lambda Dz) the GPU does not keep.
inline constexpr int kQueryOceanChannels = 11;

// height() on a spectral ocean answers the displaced point's y within this times
// (1 + |x| + |z|) metres: the Newton steps stop within kQueryHeightTolerance of (x, z), and
// the sea's slope over the horizontal map's conditioning (|grad h| / J) carries that
// into the height (docs/queries.md).
inline constexpr double kQueryOceanHeightTolerance = 1e-12;

// The state's type, init, update and sample functions for `settings` (cascade count and
// each cascade's N fix the struct's size), prefixed by `prefix` (cGraphPrefix), in C or JavaScript.
// The C text needs <stdint.h>; the spectrum's physics and the transform are shared helpers,
// guarded so that two headers in one program define them once.
std::string queryOceanC(const std::string& prefix, const ocean::OceanSettings& settings);
std::string queryOceanJs(const std::string& prefix, const ocean::OceanSettings& settings);

// What the ocean's JavaScript needs beside the math names (queryJsMathHelpers): the
// spectrum's physics, the counter-based Gaussian numbers, the 32-bit phases, the transform.
const char* queryOceanJsHelpers();
// A JavaScript function `name()` returning {h0, frequency}: per cascade the initial
// amplitudes (a Float64Array of re, im per bin, row iz * N + ix) and the bins' frequency
// indices (a Uint32Array), as core/ocean_spectrum.h draws them. The query's state and the
// web clients' ocean module (codegen/ocean_module_js.h) both call it.
std::string queryOceanSpectraJs(const std::string& name, const ocean::OceanSettings& settings);

// The state's size in bytes in C (sizeof wg_<graph>_ocean, up to padding), for the docs and
// the header's comment.
size_t queryOceanStateBytes(const ocean::OceanSettings& settings);

}  // namespace wg
