#pragma once
// The spectral ocean's persistent foam: each cascade keeps a foam map on its own grid that
// decays exponentially and grows where that cascade's surface folds (its Jacobian J below a
// threshold), stepped at a fixed interval so that a frame's foam does not depend on the
// frame rate:
//
//   f_0 = 0 at step s - K,   f_(m+1) = min(1, f_m e^(-step/decay) + growth step max(0, threshold - J(t_(m+1))))
//
// with t_m = m step. The foam at time t is f_n + (f_(n+1) - f_n)(t - t_n) / step, n = floor(t / step),
// so that it moves smoothly between steps. A still frame replays the last K = historySteps
// steps from no foam (older foam has decayed below e^-5, under 1 %); an animation may
// continue its previous frame's state instead (the recurrence is a contraction, so it and
// the replay differ by at most e^(-K step / decay)). J is the cascade's own: the cascades'
// grids have no common period on which their sum could be kept.
#include <cstdint>
#include <optional>
#include <vector>

#include "core/ocean_fft_reference.h"
#include "core/ocean_spectrum.h"

namespace wg::ocean {

struct FoamSettings {
  double threshold = 0.6;  // J below which foam grows (a cascade's own J stays nearer 1 than the sum's)
  double growth = 3;       // foam per second per unit of J below the threshold
  double decay = 1.5;      // s: the time foam takes to fall to 1/e
  double step = 0.1;       // s: the interval at which the foam is stepped
  int cascades = 4;        // only the first (longest) this many cascades make foam
};

inline constexpr double kFoamMinStep = 0.02, kFoamMaxStep = 1.0;
inline constexpr double kFoamMaxDecaySteps = 100;  // decay / step: bounds a still frame's replay
inline constexpr double kFoamHistoryDecays = 5;    // a replay covers this many decay times

std::optional<SettingError> validateFoam(const FoamSettings& f);

// K: the steps a still frame replays, ceil(kFoamHistoryDecays decay / step).
int historySteps(const FoamSettings& f);
// n = floor(t / step) (0 for a time that is not finite, as the simulation's clock).
std::int64_t stepIndex(const FoamSettings& f, double time);
// (t - t_n) / step in [0, 1]: how far t is from f_n towards f_(n+1) (0 for a time that is
// not finite).
double foamFraction(const FoamSettings& f, double time);
// The factor the foam keeps over one step, e^(-step / decay), and the gain per unit of J
// below the threshold, growth step.
double foamKeep(const FoamSettings& f);
double foamGain(const FoamSettings& f);

// One step of the recurrence at one texel.
inline double foamStep(double previous, double jacobian, double keep, double gain, double threshold) {
  double grown = previous * keep + gain * (threshold - jacobian > 0 ? threshold - jacobian : 0.0);
  return grown < 1.0 ? grown : 1.0;
}

// The double reference: a cascade's foam maps f_n and f_(n+1) (index jz * N + jx), replayed
// from no foam at step n - K with the Jacobians by FFTW.
struct FoamMaps {
  std::int64_t step = 0;  // n
  std::vector<double> current, next;
};
FoamMaps replayFoam(const OceanCascade& cascade, double choppiness, const FoamSettings& f, std::int64_t step);

}  // namespace wg::ocean
