// The ocean simulation pass's state (runtime/ocean_simulation.h).
#include "runtime/ocean_simulation.h"

#include <algorithm>
#include <string>

#include "core/node_options.h"
#include "core/ocean_settings.h"
#include "nodes/registry.h"
#include "runtime/runtime_error.h"

namespace wg::rt {

OceanSimulation::OceanSimulation(const std::vector<OceanInfo>& oceans, const std::vector<TextureInfo>& textures,
                                 SceneShaderApi api) {
  const NodeSpec* spec = defaultRegistry().find("ocean_spectrum");
  if (!spec) throw std::logic_error("the registry has no ocean_spectrum node");
  for (const OceanInfo& info : oceans) {
    const std::string what = "ocean " + info.nodeId;
    if (!info.options.is_object()) manifestError(what + " has no options object");
    for (auto it = info.options.begin(); it != info.options.end(); ++it) {
      int i = spec->optionIndex(it.key());
      if (i < 0) manifestError(what + " has an unknown option '" + it.key() + "'");
      std::string why = checkOption(spec->options[static_cast<size_t>(i)], it.value(), "");
      if (!why.empty()) manifestError(what + ": option '" + it.key() + "' " + why);
    }
    auto parsed = parseOptions(*spec, completeOptions(*spec, info.options));
    const auto& settings = parsed->as<ocean::OceanSettings>();
    if (auto e = ocean::validateOcean(settings)) manifestError(what + ": option '" + e->parameter + "' " + e->message);
    Ocean o;
    o.choppiness = settings.cascades.choppiness;
    for (size_t c = 0; c < settings.cascades.tileLengths.size(); ++c) {
      const OceanMapRef slopes{static_cast<int>(oceans_.size()), static_cast<int>(c), ocean::kSlopeMap};
      bool slopesRead = std::any_of(textures.begin(), textures.end(),
                                    [&](const TextureInfo& t) { return t.ocean && *t.ocean == slopes; });
      o.cascades.push_back(std::make_unique<OceanGpuCascade>(
          ocean::initialCascade(settings.spectrum, settings.cascades, static_cast<int>(c)), api, slopesRead));
    }
    oceans_.push_back(std::move(o));
  }
}

void OceanSimulation::update(double time) {
  for (auto& o : oceans_)
    for (auto& c : o.cascades) c->update(time, o.choppiness);
}

bool OceanSimulation::computesSlopes(int ocean, int cascade) const {
  return oceans_.at(static_cast<size_t>(ocean)).cascades.at(static_cast<size_t>(cascade))->computesSlopes();
}

GLuint OceanSimulation::map(const OceanMapRef& ref) const {
  if (ref.ocean < 0 || static_cast<size_t>(ref.ocean) >= oceans_.size() || ref.cascade < 0 ||
      static_cast<size_t>(ref.cascade) >= oceans_[static_cast<size_t>(ref.ocean)].cascades.size())
    manifestError("an ocean texture names ocean " + std::to_string(ref.ocean) + " cascade " + std::to_string(ref.cascade) +
                  ", which the manifest's \"oceans\" does not describe");
  const OceanGpuCascade& c = *oceans_[static_cast<size_t>(ref.ocean)].cascades[static_cast<size_t>(ref.cascade)];
  if (ref.map == ocean::kSlopeMap && !c.computesSlopes())
    manifestError("an ocean texture reads the slope map of ocean " + std::to_string(ref.ocean) + " cascade " +
                  std::to_string(ref.cascade) + ", which the simulation was not asked to compute");
  return ref.map == ocean::kSlopeMap ? c.slopeMap() : c.displacementMap();
}

}  // namespace wg::rt
