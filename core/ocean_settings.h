#pragma once
// What an ocean_spectrum node describes: the spectrum and the cascades it is sampled on.
// The node parses its options into this struct; the readers' GLSL, the planner (which maps
// and passes to make) and the CPU reference all read it from there.
#include <optional>
#include <string>

#include "core/ocean_fft_reference.h"
#include "core/ocean_foam.h"
#include "core/ocean_spectrum.h"

namespace wg::ocean {

// The maps each cascade fills (runtime/ocean_gpu_cascade.h, runtime/ocean_gpu_foam.h):
//   displacement (RGBA32F): (lambda Dx, h, lambda Dz, lambda dDx/dz)
//   slopes (RGBA32F):       (dh/dx, dh/dz, lambda dDx/dx, lambda dDz/dz)
//   foam (R32F):            the persistent foam in [0, 1] (core/ocean_foam.h)
//   moments (RGBA32F):      (dh/dx^2, dh/dz^2, dh/dx dh/dz, lambda dDx/dz), read only by the
//                           filtered reader (ocean_surface's `filter`); a cascade whose moments
//                           a shader reads is filtered: its slope and moments maps carry mip
//                           pyramids of 2x2 box means down to 1 x 1 (nodes/ocean_filter.h)
enum OceanMap : int { kDisplacementMap = 0, kSlopeMap = 1, kFoamMap = 2, kMomentsMap = 3 };
inline constexpr int kOceanMapCount = 4;
inline constexpr const char* kOceanMapNames[kOceanMapCount] = {"displacement", "slopes", "foam", "moments"};

struct OceanSettings {
  SpectrumSettings spectrum;
  CascadeSettings cascades;
  FoamSettings foam;
};

// Whether cascade `cascade` makes foam (the first foam.cascades of them).
bool makesFoam(const OceanSettings& s, int cascade);

// The most texel steps a still frame's foam replay may run: (K + 1) steps on every foam
// cascade's N^2 grid. The defaults run 15 million (76 x 3 x 256^2, about 6 s on llvmpipe);
// the budget keeps the worst a setting can ask (501 steps on four 512^2 cascades, 525
// million: minutes per frame there) out, and allows the default foam at fft_size 512.
inline constexpr double kFoamReplayBudget = 134217728;  // 2^27

// The texel steps a still frame's foam replay runs with these settings.
double foamReplayTexelSteps(const OceanSettings& s);

// Why settings are meaningless (the option's name and a sentence), or nothing. A foam
// replay over kFoamReplayBudget is an error at foam_decay, naming the other settings.
std::optional<SettingError> validateOcean(const OceanSettings& s);

// Every field of the settings as text with all the digits a double holds: two settings
// with the same key make the same sea bit for bit (the reference's cache and the
// runtime's simulations are keyed by it).
std::string settingsKey(const OceanSettings& s);

}  // namespace wg::ocean
