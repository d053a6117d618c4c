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
enum OceanMap : int { kDisplacementMap = 0, kSlopeMap = 1, kFoamMap = 2 };
inline constexpr int kOceanMapCount = 3;
inline constexpr const char* kOceanMapNames[kOceanMapCount] = {"displacement", "slopes", "foam"};

struct OceanSettings {
  SpectrumSettings spectrum;
  CascadeSettings cascades;
  FoamSettings foam;
};

// Whether cascade `cascade` makes foam (the first foam.cascades of them).
bool makesFoam(const OceanSettings& s, int cascade);

// Why settings are meaningless (the option's name and a sentence), or nothing.
std::optional<SettingError> validateOcean(const OceanSettings& s);

// Every field of the settings as text with all the digits a double holds: two settings
// with the same key make the same sea bit for bit (the reference's cache and the
// runtime's simulations are keyed by it).
std::string settingsKey(const OceanSettings& s);

}  // namespace wg::ocean
