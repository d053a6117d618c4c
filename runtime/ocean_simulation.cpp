// The ocean simulation pass's state (runtime/ocean_simulation.h).
#include "runtime/ocean_simulation.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "runtime/ocean_manifest.h"
#include "runtime/runtime_error.h"

namespace wg::rt {

OceanSimulation::OceanSimulation(const std::vector<OceanInfo>& oceans, const std::vector<TextureInfo>& textures,
                                 SceneShaderApi api)
    : identity_(identity(oceans, textures)) {
  for (const OceanInfo& info : oceans) {
    const ocean::OceanSettings settings = manifestOceanSettings(info);
    Ocean o;
    o.choppiness = settings.cascades.choppiness;
    const int index = static_cast<int>(oceans_.size());
    for (int c = 0; c < static_cast<int>(settings.cascades.tileLengths.size()); ++c) {
      const bool foam = oceanFoamRead(textures, settings, index, c, info.nodeId);
      o.cascades.push_back(std::make_unique<OceanGpuCascade>(ocean::initialCascade(settings.spectrum, settings.cascades, c),
                                                             api, oceanMapRead(textures, index, c, ocean::kSlopeMap), foam));
      o.foam.push_back(foam ? std::make_unique<OceanGpuFoam>(settings.cascades.resolution, settings.foam, api) : nullptr);
    }
    oceans_.push_back(std::move(o));
  }
}

std::string OceanSimulation::identity(const std::vector<OceanInfo>& oceans, const std::vector<TextureInfo>& textures) {
  return oceanSimulationIdentity(oceans, textures);
}

size_t OceanSimulation::textureBytes(const std::vector<OceanInfo>& oceans, const std::vector<TextureInfo>& textures) {
  size_t bytes = 0;
  for (size_t o = 0; o < oceans.size(); ++o) {
    const ocean::OceanSettings settings = manifestOceanSettings(oceans[o]);
    for (int c = 0; c < static_cast<int>(settings.cascades.tileLengths.size()); ++c) {
      bytes += OceanGpuCascade::textureBytes(settings.cascades.resolution,
                                             oceanMapRead(textures, static_cast<int>(o), c, ocean::kSlopeMap));
      if (oceanFoamRead(textures, settings, static_cast<int>(o), c, oceans[o].nodeId))
        bytes += OceanGpuFoam::textureBytes(settings.cascades.resolution);
    }
  }
  return bytes;
}

void OceanSimulation::update(double time) {
  // Equal times only (a NaN never equals itself, so it always runs).
  lastUpdateRan_ = !(heldAt_ && heldAt_->first == time && heldAt_->second == foamHistory_);
  if (!lastUpdateRan_) return;
  heldAt_.reset();  // a throw below leaves no claim on the maps
  ++updatesRun_;
  for (auto& o : oceans_)
    for (size_t c = 0; c < o.cascades.size(); ++c) {
      // The foam first: its steps use the cascade's scratch spectra, which update refills.
      if (o.foam[c]) o.foam[c]->update(time, o.choppiness, *o.cascades[c], foamHistory_);
      o.cascades[c]->update(time, o.choppiness);
    }
  heldAt_.emplace(time, foamHistory_);
}

int OceanSimulation::lastFoamSteps() const {
  int steps = 0;
  if (!lastUpdateRan_) return steps;
  for (const auto& o : oceans_)
    for (const auto& f : o.foam)
      if (f) steps += f->lastSteps();
  return steps;
}

bool OceanSimulation::computesFoam(int ocean, int cascade) const {
  return oceans_.at(static_cast<size_t>(ocean)).foam.at(static_cast<size_t>(cascade)) != nullptr;
}

bool OceanSimulation::computesSlopes(int ocean, int cascade) const {
  return oceans_.at(static_cast<size_t>(ocean)).cascades.at(static_cast<size_t>(cascade))->computesSlopes();
}

GLuint OceanSimulation::map(const OceanMapRef& ref) const {
  std::vector<size_t> cascades;
  for (const Ocean& o : oceans_) cascades.push_back(o.cascades.size());
  checkOceanMapRef(ref, cascades);
  const OceanGpuCascade& c = *oceans_[static_cast<size_t>(ref.ocean)].cascades[static_cast<size_t>(ref.cascade)];
  if (ref.map == ocean::kSlopeMap && !c.computesSlopes())
    manifestError("an ocean texture reads the slope map of ocean " + std::to_string(ref.ocean) + " cascade " +
                  std::to_string(ref.cascade) + ", which the simulation was not asked to compute");
  if (ref.map == ocean::kFoamMap) {
    if (!computesFoam(ref.ocean, ref.cascade))
      manifestError("an ocean texture reads the foam of ocean " + std::to_string(ref.ocean) + " cascade " +
                    std::to_string(ref.cascade) + ", which the simulation was not asked to compute");
    return oceans_[static_cast<size_t>(ref.ocean)].foam[static_cast<size_t>(ref.cascade)]->map();
  }
  return ref.map == ocean::kSlopeMap ? c.slopeMap() : c.displacementMap();
}

}  // namespace wg::rt
