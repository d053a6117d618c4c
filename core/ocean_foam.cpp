// The spectral ocean's persistent foam (core/ocean_foam.h).
#include "core/ocean_foam.h"

#include <algorithm>
#include <cmath>
#include <string>


namespace wg::ocean {

std::optional<SettingError> validateFoam(const FoamSettings& f) {
  auto error = [](std::string p, std::string m) { return std::optional<SettingError>(SettingError{p, m}); };
  if (!std::isfinite(f.threshold) || f.threshold < -1 || f.threshold > 2)
    return error("foam_threshold", numberText(f.threshold) + " is outside [-1, 2]");
  if (!std::isfinite(f.growth) || f.growth < 0 || f.growth > 1000)
    return error("foam_growth", numberText(f.growth) + " is outside [0, 1000]");
  if (!std::isfinite(f.step) || f.step < kFoamMinStep || f.step > kFoamMaxStep)
    return error("foam_step", numberText(f.step) + " s is outside [" + numberText(kFoamMinStep) + ", " +
                                  numberText(kFoamMaxStep) + "]");
  if (!std::isfinite(f.decay) || !(f.decay > 0))
    return error("foam_decay", numberText(f.decay) + " s must be a finite number greater than 0");
  if (f.decay > kFoamMaxDecaySteps * f.step)
    return error("foam_decay", numberText(f.decay) + " s is more than " + numberText(kFoamMaxDecaySteps) +
                                   " foam steps of " + numberText(f.step) +
                                   " s: a still frame replays the foam's last " + numberText(kFoamHistoryDecays) +
                                   " decay times, so make foam_step at least foam_decay / " +
                                   numberText(kFoamMaxDecaySteps));
  if (f.cascades < 1 || f.cascades > kMaxCascades)
    return error("foam_cascades", std::to_string(f.cascades) + " is outside [1, " + std::to_string(kMaxCascades) + "]");
  return std::nullopt;
}

int historySteps(const FoamSettings& f) {
  // Less a hair, so that a whole ratio (1.5 s in steps of 0.1 s) is not rounded up a step.
  return static_cast<int>(std::ceil(kFoamHistoryDecays * f.decay / f.step - 1e-9));
}

std::int64_t stepIndex(const FoamSettings& f, double time) {
  if (!std::isfinite(time)) return 0;
  // Times past 2^53 steps would not be whole; no clock a scene uses comes near.
  return static_cast<std::int64_t>(std::floor(time / f.step));
}

double foamFraction(const FoamSettings& f, double time) {
  if (!std::isfinite(time)) return 0;
  double fraction = (time - static_cast<double>(stepIndex(f, time)) * f.step) / f.step;
  return std::clamp(fraction, 0.0, 1.0);
}

double foamKeep(const FoamSettings& f) { return std::exp(-f.step / f.decay); }
double foamGain(const FoamSettings& f) { return f.growth * f.step; }

FoamMaps replayFoam(const OceanCascade& cascade, double choppiness, const FoamSettings& f, std::int64_t step) {
  const size_t count = static_cast<size_t>(cascade.resolution) * cascade.resolution;
  const double keep = foamKeep(f), gain = foamGain(f);
  FoamMaps out;
  out.step = step;
  std::vector<double> foam(count, 0.0);
  // f at step - K is 0; K + 1 steps reach f_(n+1).
  const int k = historySteps(f);
  for (std::int64_t m = step - k + 1; m <= step + 1; ++m) {
    std::vector<double> j = oceanJacobian(cascade, static_cast<double>(m) * f.step, choppiness);
    for (size_t i = 0; i < count; ++i) foam[i] = foamStep(foam[i], j[i], keep, gain, f.threshold);
    if (m == step) out.current = foam;
  }
  out.next = std::move(foam);
  return out;
}

}  // namespace wg::ocean
