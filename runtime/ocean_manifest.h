#pragma once
// What both runtimes' ocean simulations (runtime/ocean_simulation.h for GL,
// runtime/vk_ocean_simulation.h for Vulkan) read from a manifest: each ocean's settings,
// which of its maps a shader samples, and the identity of what they simulate.
#include <string>
#include <vector>

#include "codegen/shader_plan.h"
#include "core/ocean_settings.h"

namespace wg::rt {

// An ocean's settings from the manifest's options, parsed with the ocean_spectrum node's
// own parser and checked as the compiler checks them (a manifest error otherwise).
ocean::OceanSettings manifestOceanSettings(const OceanInfo& info);
// Whether a shader samples map `map` of cascade `cascade` of ocean `ocean`.
bool oceanMapRead(const std::vector<TextureInfo>& textures, int ocean, int cascade, int map);
// Whether the foam of that cascade is read (a manifest error where the settings give that
// cascade no foam: no shader the compiler writes samples one).
bool oceanFoamRead(const std::vector<TextureInfo>& textures, const ocean::OceanSettings& settings, int ocean, int cascade,
                   const std::string& nodeId);
// What a simulation computes, as text: two manifests with equal identities (each ocean's id
// and options, each ocean map a shader reads) can share one simulation.
std::string oceanSimulationIdentity(const std::vector<OceanInfo>& oceans, const std::vector<TextureInfo>& textures);
// A manifest error for a map reference outside the oceans (`cascades[o]` cascades each).
void checkOceanMapRef(const OceanMapRef& ref, const std::vector<size_t>& cascades);

}  // namespace wg::rt
