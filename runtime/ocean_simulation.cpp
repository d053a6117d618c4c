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

// Whether a shader samples map `map` of cascade `cascade` of ocean `ocean`.
bool mapRead(const std::vector<TextureInfo>& textures, int ocean, int cascade, int map) {
  const OceanMapRef ref{ocean, cascade, map};
  return std::any_of(textures.begin(), textures.end(), [&](const TextureInfo& t) { return t.ocean && *t.ocean == ref; });
}

// Whether the foam of cascade `cascade` of ocean `ocean` is read (a manifest error where
// the settings give that cascade no foam: no shader the compiler writes samples one).
bool foamRead(const std::vector<TextureInfo>& textures, const ocean::OceanSettings& settings, int ocean, int cascade,
              const std::string& nodeId) {
  if (!mapRead(textures, ocean, cascade, ocean::kFoamMap)) return false;
  if (!ocean::makesFoam(settings, cascade))
    manifestError("an ocean texture reads the foam of ocean " + nodeId + " cascade " + std::to_string(cascade) +
                  ", which its foam_cascades gives no foam");
  return true;
}

}  // namespace

OceanSimulation::OceanSimulation(const std::vector<OceanInfo>& oceans, const std::vector<TextureInfo>& textures,
                                 SceneShaderApi api)
    : identity_(identity(oceans, textures)) {
  for (const OceanInfo& info : oceans) {
    const ocean::OceanSettings settings = oceanSettings(info);
    Ocean o;
    o.choppiness = settings.cascades.choppiness;
    const int index = static_cast<int>(oceans_.size());
    for (int c = 0; c < static_cast<int>(settings.cascades.tileLengths.size()); ++c) {
      const bool foam = foamRead(textures, settings, index, c, info.nodeId);
      o.cascades.push_back(std::make_unique<OceanGpuCascade>(ocean::initialCascade(settings.spectrum, settings.cascades, c),
                                                             api, mapRead(textures, index, c, ocean::kSlopeMap), foam));
      o.foam.push_back(foam ? std::make_unique<OceanGpuFoam>(settings.cascades.resolution, settings.foam, api) : nullptr);
    }
    oceans_.push_back(std::move(o));
  }
}

std::string OceanSimulation::identity(const std::vector<OceanInfo>& oceans, const std::vector<TextureInfo>& textures) {
  std::string text;
  for (const OceanInfo& info : oceans) text += info.nodeId + '\0' + info.options.dump() + '\n';
  for (const TextureInfo& t : textures)
    if (t.ocean)
      text += std::to_string(t.ocean->ocean) + ' ' + std::to_string(t.ocean->cascade) + ' ' + std::to_string(t.ocean->map) + '\n';
  return text;
}

size_t OceanSimulation::textureBytes(const std::vector<OceanInfo>& oceans, const std::vector<TextureInfo>& textures) {
  size_t bytes = 0;
  for (size_t o = 0; o < oceans.size(); ++o) {
    const ocean::OceanSettings settings = oceanSettings(oceans[o]);
    for (int c = 0; c < static_cast<int>(settings.cascades.tileLengths.size()); ++c) {
      bytes += OceanGpuCascade::textureBytes(settings.cascades.resolution,
                                             mapRead(textures, static_cast<int>(o), c, ocean::kSlopeMap));
      if (foamRead(textures, settings, static_cast<int>(o), c, oceans[o].nodeId))
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
  if (ref.ocean < 0 || static_cast<size_t>(ref.ocean) >= oceans_.size() || ref.cascade < 0 ||
      static_cast<size_t>(ref.cascade) >= oceans_[static_cast<size_t>(ref.ocean)].cascades.size())
    manifestError("an ocean texture names ocean " + std::to_string(ref.ocean) + " cascade " + std::to_string(ref.cascade) +
                  ", which the manifest's \"oceans\" does not describe");
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
