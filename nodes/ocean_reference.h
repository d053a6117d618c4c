#pragma once
// The ocean readers' double-precision reference: each distinct ocean_spectrum setting is
// registered once (the id travels in the `ocean` Value's first component), its cascades'
// fields are computed by core/ocean_fft_reference.h at each time asked for and kept for
// the next look-ups at that time, and a look-up is the interpolation the GLSL performs:
// bilinear between the four texels around the point (wg_ocean_map, the pyramids' levels,
// the foam), or bicubic (Catmull-Rom) between the 4 x 4 around it where the vertex stage
// reads (wg_ocean_map_cubic).
#include <array>
#include <vector>

#include "core/ocean_settings.h"

namespace wg::nodes::oceanref {

// The id of `settings` (the same id for the same settingsKey); process-wide, thread-safe.
int registerOcean(const ocean::OceanSettings& settings);
const ocean::OceanSettings& settingsOf(int id);

// What the maps hold at a point, summed over the cascades with their weights: as the GPU's
// two RGBA maps, (lambda Dx, h, lambda Dz, lambda dDx/dz) and
// (dh/dx, dh/dz, lambda dDx/dx, lambda dDz/dz).
struct MapSample {
  std::array<double, 4> displacement{};
  std::array<double, 4> slopes{};
};
// Cascade `cascade` of ocean `id` at time t, at the world point (x, z): bilinear as
// wg_ocean_map, or bicubic as wg_ocean_map_cubic.
MapSample sampleCascade(int id, int cascade, double time, double x, double z, bool bicubic);

// What the filtered reader (wg_ocean_map_lod) reads of a cascade: its slope map and its
// moments map (dh/dx^2, dh/dz^2, dh/dx dh/dz, lambda dDx/dz) at level of detail lod, from
// pyramids of 2x2 box means made in double from the double maps (the GPU's downsample pass
// in exact arithmetic), trilinear as the shader reads them.
struct FilteredSample {
  std::array<double, 4> slopes{};
  std::array<double, 4> moments{};
};
FilteredSample sampleCascadeFiltered(int id, int cascade, double time, double x, double z, double lod);

// Level `level` (0: the map) of a cascade's slope or moments pyramid at time t, (n >> level)^2
// texels, row jz * (n >> level) + jx: what the GPU's pyramid is tested against.
const std::vector<std::array<double, 4>>& pyramidLevel(int id, int cascade, double time, bool moments, int level);
// The persistent foam of cascade `cascade` at time t at the world point (x, z): bilinear in
// the replayed maps f_n and f_(n+1) (core/ocean_foam.h), then between them in time; 0 for a
// cascade that makes no foam.
double sampleFoam(int id, int cascade, double time, double x, double z);

}  // namespace wg::nodes::oceanref
