// The spectral oceans on Vulkan (runtime/vk_ocean_simulation.h).
#include "runtime/vk_ocean_simulation.h"

#include "runtime/ocean_manifest.h"
#include "runtime/runtime_error.h"

namespace wg::rt {

VkOceanSimulation::VkOceanSimulation(VkContext& context, const std::vector<OceanInfo>& oceans,
                                     const std::vector<TextureInfo>& textures)
    : passes_(std::make_unique<VkOceanPasses>(context)), identity_(identity(oceans, textures)) {
  for (const OceanInfo& info : oceans) {
    const ocean::OceanSettings settings = manifestOceanSettings(info);
    Ocean o;
    o.choppiness = settings.cascades.choppiness;
    const int index = static_cast<int>(oceans_.size());
    for (int c = 0; c < static_cast<int>(settings.cascades.tileLengths.size()); ++c) {
      const bool foam = oceanFoamRead(textures, settings, index, c, info.nodeId);
      o.cascades.push_back(std::make_unique<VkOceanCascade>(*passes_, ocean::initialCascade(settings.spectrum, settings.cascades, c),
                                                            oceanMapRead(textures, index, c, ocean::kSlopeMap), foam));
      o.foam.push_back(foam ? std::make_unique<VkOceanFoam>(*passes_, settings.cascades.resolution, settings.foam) : nullptr);
    }
    oceans_.push_back(std::move(o));
  }
}

std::string VkOceanSimulation::identity(const std::vector<OceanInfo>& oceans, const std::vector<TextureInfo>& textures) {
  return oceanSimulationIdentity(oceans, textures);
}

void VkOceanSimulation::record(VkCommandBuffer cmd, double time) {
  // Equal times only (a NaN never equals itself, so it always records).
  lastRecordRan_ = !(heldAt_ && heldAt_->first == time && heldAt_->second == foamHistory_);
  if (!lastRecordRan_) return;
  heldAt_.reset();  // a throw below leaves no claim on the maps
  ++updatesRecorded_;
  for (auto& o : oceans_)
    for (size_t c = 0; c < o.cascades.size(); ++c) {
      // The foam first: its steps use the cascade's scratch spectra, which the maps' passes refill.
      if (o.foam[c]) o.foam[c]->record(cmd, time, o.choppiness, *o.cascades[c], foamHistory_);
      o.cascades[c]->record(cmd, time, o.choppiness);
    }
  heldAt_.emplace(time, foamHistory_);
}

int VkOceanSimulation::lastFoamSteps() const {
  int steps = 0;
  if (!lastRecordRan_) return steps;
  for (const auto& o : oceans_)
    for (const auto& f : o.foam)
      if (f) steps += f->lastSteps();
  return steps;
}

bool VkOceanSimulation::computesFoam(int ocean, int cascade) const {
  return oceans_.at(static_cast<size_t>(ocean)).foam.at(static_cast<size_t>(cascade)) != nullptr;
}

bool VkOceanSimulation::computesSlopes(int ocean, int cascade) const {
  return oceans_.at(static_cast<size_t>(ocean)).cascades.at(static_cast<size_t>(cascade))->computesSlopes();
}

VkImageOwner& VkOceanSimulation::map(const OceanMapRef& ref) {
  std::vector<size_t> cascades;
  for (const Ocean& o : oceans_) cascades.push_back(o.cascades.size());
  checkOceanMapRef(ref, cascades);
  Ocean& o = oceans_[static_cast<size_t>(ref.ocean)];
  VkOceanCascade& c = *o.cascades[static_cast<size_t>(ref.cascade)];
  const std::string which = "ocean " + std::to_string(ref.ocean) + " cascade " + std::to_string(ref.cascade);
  if (ref.map == ocean::kFoamMap) {
    if (!computesFoam(ref.ocean, ref.cascade))
      manifestError("an ocean texture reads the foam of " + which + ", which the simulation was not asked to compute");
    return o.foam[static_cast<size_t>(ref.cascade)]->map();
  }
  if (ref.map == ocean::kSlopeMap) {
    if (!c.computesSlopes())
      manifestError("an ocean texture reads the slope map of " + which + ", which the simulation was not asked to compute");
    return c.slopeMap();
  }
  return c.displacementMap();
}

}  // namespace wg::rt
