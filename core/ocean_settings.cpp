// The ocean_spectrum node's settings (core/ocean_settings.h).
#include "core/ocean_settings.h"

#include <algorithm>
#include <cstdio>

namespace wg::ocean {

double foamReplayTexelSteps(const OceanSettings& s) {
  double texels = 0;  // over the foam cascades, each on its own grid
  for (size_t c = 0; c < s.cascades.tileLengths.size(); ++c)
    if (makesFoam(s, static_cast<int>(c))) {
      const double n = cascadeResolution(s.cascades, c);
      texels += n * n;
    }
  return (historySteps(s.foam) + 1.0) * texels;
}

namespace {
int largestFoamResolution(const OceanSettings& s) {
  int n = 0;
  for (size_t c = 0; c < s.cascades.tileLengths.size(); ++c)
    if (makesFoam(s, static_cast<int>(c))) n = std::max(n, cascadeResolution(s.cascades, c));
  return n;
}
}  // namespace

std::optional<SettingError> validateOcean(const OceanSettings& s) {
  if (auto e = validateSpectrum(s.spectrum)) return e;
  if (auto e = validateCascades(s.cascades)) return e;
  if (auto e = validateFoam(s.foam)) return e;
  const double steps = foamReplayTexelSteps(s);
  if (steps > kFoamReplayBudget) {
    char text[320];
    std::snprintf(text, sizeof text,
                  "%s s makes a still frame replay %d foam steps on %d cascades of up to %d^2 (%.0f million texel "
                  "steps, over the budget of %.0f million): raise foam_step, or lower foam_decay, foam_cascades, "
                  "fft_size or cascade_sizes",
                  numberText(s.foam.decay).c_str(), historySteps(s.foam) + 1,
                  static_cast<int>(std::min<size_t>(static_cast<size_t>(s.foam.cascades), s.cascades.tileLengths.size())),
                  largestFoamResolution(s), steps / 1e6, kFoamReplayBudget / 1e6);
    return SettingError{"foam_decay", text};
  }
  return std::nullopt;
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
  add(static_cast<double>(c.sizes.size()));
  for (int n : c.sizes) add(n);
  add(c.choppiness);
  add(static_cast<double>(c.seed));
  for (double l : c.tileLengths) add(l);
  const FoamSettings& f = s.foam;
  for (double x : {f.threshold, f.growth, f.decay, f.step}) add(x);
  add(f.cascades);
  return key;
}

}  // namespace wg::ocean
