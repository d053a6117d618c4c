// The ocean_spectrum node's settings (core/ocean_settings.h).
#include "core/ocean_settings.h"

#include <cstdio>

namespace wg::ocean {

std::optional<SettingError> validateOcean(const OceanSettings& s) {
  if (auto e = validateSpectrum(s.spectrum)) return e;
  if (auto e = validateCascades(s.cascades)) return e;
  return validateFoam(s.foam);
}

bool makesFoam(const OceanSettings& s, int cascade) {
  return cascade >= 0 && cascade < s.foam.cascades && static_cast<size_t>(cascade) < s.cascades.tileLengths.size();
}

std::string settingsKey(const OceanSettings& s) {
  std::string key;
  auto add = [&key](double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g ", x);
    key += buf;
  };
  const SpectrumSettings& p = s.spectrum;
  add(static_cast<double>(p.model));
  add(static_cast<double>(p.spreading));
  for (double x : {p.windSpeed, p.windDirection, p.fetch, p.depth, p.gamma, p.phillipsAmplitude, p.phillipsSmallWave,
                   p.swell.height, p.swell.period, p.swell.direction, p.swell.spread})
    add(x);
  const CascadeSettings& c = s.cascades;
  add(c.resolution);
  add(c.choppiness);
  add(static_cast<double>(c.seed));
  for (double l : c.tileLengths) add(l);
  const FoamSettings& f = s.foam;
  for (double x : {f.threshold, f.growth, f.decay, f.step}) add(x);
  add(f.cascades);
  return key;
}

}  // namespace wg::ocean
