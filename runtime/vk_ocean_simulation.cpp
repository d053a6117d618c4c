// The spectral oceans on Vulkan (runtime/vk_ocean_simulation.h).
#include "runtime/vk_ocean_simulation.h"

#include "runtime/ocean_manifest.h"

namespace wg::rt {

VkOceanSimulation::VkOceanSimulation(VkContext& context, const std::vector<OceanInfo>& oceans,
                                     const std::vector<TextureInfo>& textures)
    : passes_(std::make_unique<VkOceanPasses>(context)),
      set_(
          oceans, textures,
          [this](const ocean::OceanSettings& settings, int, int c, bool slopes, bool foam, bool filtered) {
            return std::make_unique<VkOceanCascade>(*passes_, ocean::initialCascade(settings.spectrum, settings.cascades, c),
                                                    slopes, foam, filtered);
          },
          [this](const ocean::OceanSettings& settings, int c) {
            return std::make_unique<VkOceanFoam>(
                *passes_, ocean::cascadeResolution(settings.cascades, static_cast<size_t>(c)), settings.foam);
          }),
      identity_(identity(oceans, textures)) {}

std::string VkOceanSimulation::identity(const std::vector<OceanInfo>& oceans, const std::vector<TextureInfo>& textures) {
  return oceanSimulationIdentity(oceans, textures);
}

void VkOceanSimulation::record(VkCommandBuffer cmd, double time) {
  set_.advance(time, [cmd, time](VkOceanFoam* foam, VkOceanCascade& cascade, double choppiness, FoamHistory history) {
    // The foam first: its steps use the cascade's scratch spectra, which the maps' passes refill.
    if (foam) foam->record(cmd, time, choppiness, cascade, history);
    cascade.record(cmd, time, choppiness);
  });
}

VkImageOwner& VkOceanSimulation::map(const OceanMapRef& ref) {
  const auto [cascade, foam] = set_.mapSource(ref);
  if (foam) return foam->map();
  if (ref.map == ocean::kMomentsMap) return cascade->momentsMap();
  return ref.map == ocean::kSlopeMap ? cascade->slopeMap() : cascade->displacementMap();
}

}  // namespace wg::rt
