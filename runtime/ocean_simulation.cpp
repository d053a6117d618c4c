// The ocean simulation pass's state (runtime/ocean_simulation.h).
#include "runtime/ocean_simulation.h"

#include <string>

#include "core/node_options.h"
#include "core/ocean_settings.h"
#include "nodes/registry.h"
#include "runtime/runtime_error.h"

namespace wg::rt {

OceanSimulation::OceanSimulation(const std::vector<OceanInfo>& oceans, SceneShaderApi api) {
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
    for (size_t c = 0; c < settings.cascades.tileLengths.size(); ++c)
      o.cascades.push_back(std::make_unique<OceanGpuCascade>(
          ocean::initialCascade(settings.spectrum, settings.cascades, static_cast<int>(c)), api));
    oceans_.push_back(std::move(o));
  }
}

void OceanSimulation::update(double time) {
  for (auto& o : oceans_)
    for (auto& c : o.cascades) c->update(time, o.choppiness);
}

GLuint OceanSimulation::map(const OceanMapRef& ref) const {
  if (ref.ocean < 0 || static_cast<size_t>(ref.ocean) >= oceans_.size() || ref.cascade < 0 ||
      static_cast<size_t>(ref.cascade) >= oceans_[static_cast<size_t>(ref.ocean)].cascades.size())
    manifestError("an ocean texture names ocean " + std::to_string(ref.ocean) + " cascade " + std::to_string(ref.cascade) +
                  ", which the manifest's \"oceans\" does not describe");
  const OceanGpuCascade& c = *oceans_[static_cast<size_t>(ref.ocean)].cascades[static_cast<size_t>(ref.cascade)];
  return ref.map == ocean::kSlopeMap ? c.slopeMap() : c.displacementMap();
}

}  // namespace wg::rt
