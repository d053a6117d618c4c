// The ocean simulation pass's state (runtime/ocean_simulation.h).
#include "runtime/ocean_simulation.h"

#include <memory>
#include <string>

#include "runtime/ocean_manifest.h"

namespace wg::rt {

OceanSimulation::OceanSimulation(const std::vector<OceanInfo>& oceans, const std::vector<TextureInfo>& textures,
                                 SceneShaderApi api)
    : set_(
          oceans, textures,
          [api](const ocean::OceanSettings& settings, int, int c, bool slopes, bool foam, bool filtered) {
            return std::make_unique<OceanGpuCascade>(ocean::initialCascade(settings.spectrum, settings.cascades, c), api,
                                                     slopes, foam, filtered);
          },
          [api](const ocean::OceanSettings& settings, int c) {
            return std::make_unique<OceanGpuFoam>(ocean::cascadeResolution(settings.cascades, static_cast<size_t>(c)),
                                                  settings.foam, api);
          }),
      identity_(identity(oceans, textures)) {}

std::string OceanSimulation::identity(const std::vector<OceanInfo>& oceans, const std::vector<TextureInfo>& textures) {
  return oceanSimulationIdentity(oceans, textures);
}

size_t OceanSimulation::textureBytes(const std::vector<OceanInfo>& oceans, const std::vector<TextureInfo>& textures) {
  size_t bytes = 0;
  for (size_t o = 0; o < oceans.size(); ++o) {
    const ocean::OceanSettings settings = manifestOceanSettings(oceans[o]);
    for (int c = 0; c < static_cast<int>(settings.cascades.tileLengths.size()); ++c) {
      const int n = ocean::cascadeResolution(settings.cascades, static_cast<size_t>(c));
      bytes += OceanGpuCascade::textureBytes(n, oceanMapRead(textures, static_cast<int>(o), c, ocean::kSlopeMap),
                                             oceans[o].filtered);
      if (oceanFoamRead(textures, settings, static_cast<int>(o), c, oceans[o].nodeId))
        bytes += OceanGpuFoam::textureBytes(n);
    }
  }
  return bytes;
}

void OceanSimulation::update(double time) {
  set_.advance(time, [time](OceanGpuFoam* foam, OceanGpuCascade& cascade, double choppiness, FoamHistory history) {
    // The foam first: its steps use the cascade's scratch spectra, which update refills.
    if (foam) foam->update(time, choppiness, cascade, history);
    cascade.update(time, choppiness);
  });
}

GLuint OceanSimulation::map(const OceanMapRef& ref) const {
  const auto [cascade, foam] = set_.mapSource(ref);
  if (foam) return foam->map();
  if (ref.map == ocean::kMomentsMap) return cascade->momentsMap();
  return ref.map == ocean::kSlopeMap ? cascade->slopeMap() : cascade->displacementMap();
}

}  // namespace wg::rt
