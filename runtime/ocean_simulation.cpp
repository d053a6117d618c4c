// The ocean simulation pass's state (runtime/ocean_simulation.h).
#include "runtime/ocean_simulation.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/node_options.h"
#include "core/ocean_settings.h"
#include "nodes/registry.h"
#include "runtime/runtime_error.h"

namespace wg::rt {

namespace {

// An ocean's settings from the manifest's options, checked as the compiler checks them.
ocean::OceanSettings oceanSettings(const OceanInfo& info) {
  const NodeSpec* spec = defaultRegistry().find("ocean_spectrum");
  if (!spec) throw std::logic_error("the registry has no ocean_spectrum node");
  const std::string what = "ocean " + info.nodeId;
  if (!info.options.is_object()) manifestError(what + " has no options object");
  for (auto it = info.options.begin(); it != info.options.end(); ++it) {
    int i = spec->optionIndex(it.key());
    if (i < 0) manifestError(what + " has an unknown option '" + it.key() + "'");
    std::string why = checkOption(spec->options[static_cast<size_t>(i)], it.value(), "");
    if (!why.empty()) manifestError(what + ": option '" + it.key() + "' " + why);
  }
  auto parsed = parseOptions(*spec, completeOptions(*spec, info.options));
  ocean::OceanSettings settings = parsed->as<ocean::OceanSettings>();
  if (auto e = ocean::validateOcean(settings)) manifestError(what + ": option '" + e->parameter + "' " + e->message);
  return settings;
}

// Whether a shader samples the slope map of cascade `cascade` of ocean `ocean`.
bool slopeMapRead(const std::vector<TextureInfo>& textures, int ocean, int cascade) {
  const OceanMapRef slopes{ocean, cascade, ocean::kSlopeMap};
  return std::any_of(textures.begin(), textures.end(), [&](const TextureInfo& t) { return t.ocean && *t.ocean == slopes; });
}

}  // namespace

OceanSimulation::OceanSimulation(const std::vector<OceanInfo>& oceans, const std::vector<TextureInfo>& textures,
                                 SceneShaderApi api) {
  for (const OceanInfo& info : oceans) {
    const ocean::OceanSettings settings = oceanSettings(info);
    Ocean o;
    o.choppiness = settings.cascades.choppiness;
    for (size_t c = 0; c < settings.cascades.tileLengths.size(); ++c)
      o.cascades.push_back(std::make_unique<OceanGpuCascade>(
          ocean::initialCascade(settings.spectrum, settings.cascades, static_cast<int>(c)), api,
          slopeMapRead(textures, static_cast<int>(oceans_.size()), static_cast<int>(c))));
    oceans_.push_back(std::move(o));
  }
}

size_t OceanSimulation::textureBytes(const std::vector<OceanInfo>& oceans, const std::vector<TextureInfo>& textures) {
  size_t bytes = 0;
  for (size_t o = 0; o < oceans.size(); ++o) {
    const ocean::OceanSettings settings = oceanSettings(oceans[o]);
    for (size_t c = 0; c < settings.cascades.tileLengths.size(); ++c)
      bytes += OceanGpuCascade::textureBytes(settings.cascades.resolution,
                                             slopeMapRead(textures, static_cast<int>(o), static_cast<int>(c)));
  }
  return bytes;
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
