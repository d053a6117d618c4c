// The ocean_spectrum node's settings (core/ocean_settings.h).
#include "core/ocean_settings.h"

#include <cstdio>

namespace wg::ocean {

std::optional<SettingError> validateOcean(const OceanSettings& s) {
  if (auto e = validateSpectrum(s.spectrum)) return e;
  return validateCascades(s.cascades);
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
  return key;
}

}  // namespace wg::ocean
