// What the ocean simulations read from a manifest (runtime/ocean_manifest.h).
#include "runtime/ocean_manifest.h"

#include <algorithm>
#include <stdexcept>

#include "core/node_options.h"
#include "nodes/registry.h"
#include "runtime/runtime_error.h"

namespace wg::rt {

ocean::OceanSettings manifestOceanSettings(const OceanInfo& info) {
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

bool oceanMapRead(const std::vector<TextureInfo>& textures, int ocean, int cascade, int map) {
  const OceanMapRef ref{ocean, cascade, map};
  return std::any_of(textures.begin(), textures.end(), [&](const TextureInfo& t) { return t.ocean && *t.ocean == ref; });
}

bool oceanFoamRead(const std::vector<TextureInfo>& textures, const ocean::OceanSettings& settings, int ocean, int cascade,
                   const std::string& nodeId) {
  if (!oceanMapRead(textures, ocean, cascade, ocean::kFoamMap)) return false;
  if (!ocean::makesFoam(settings, cascade))
    manifestError("an ocean texture reads the foam of ocean " + nodeId + " cascade " + std::to_string(cascade) +
                  ", which its foam_cascades gives no foam");
  return true;
}

std::string oceanSimulationIdentity(const std::vector<OceanInfo>& oceans, const std::vector<TextureInfo>& textures) {
  std::string text;
  for (const OceanInfo& info : oceans) text += info.nodeId + '\0' + info.options.dump() + '\n';
  for (const TextureInfo& t : textures)
    if (t.ocean)
      text += std::to_string(t.ocean->ocean) + ' ' + std::to_string(t.ocean->cascade) + ' ' + std::to_string(t.ocean->map) + '\n';
  return text;
}

void checkOceanMapRef(const OceanMapRef& ref, const std::vector<size_t>& cascades) {
  if (ref.ocean < 0 || static_cast<size_t>(ref.ocean) >= cascades.size() || ref.cascade < 0 ||
      static_cast<size_t>(ref.cascade) >= cascades[static_cast<size_t>(ref.ocean)])
    manifestError("an ocean texture names ocean " + std::to_string(ref.ocean) + " cascade " + std::to_string(ref.cascade) +
                  ", which the manifest's \"oceans\" does not describe");
}

}  // namespace wg::rt
