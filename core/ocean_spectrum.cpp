// Wind-wave spectra, spreading and dispersion (core/ocean_spectrum.h). Every function is
// written to stay finite at the extremes the validation lets through (a calm, a gale,
// depth far below a wavelength, an unbounded fetch): ratios are formed before powers so
// that a peak frequency of infinity gives 0, not inf/inf.
#include "core/ocean_spectrum.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace wg::ocean {
namespace {

constexpr double kPiersonMoskowitzAlpha = 0.0081;  // Phillips' constant as PM use it
constexpr double kPiersonMoskowitzBeta = 0.74;     // with omega_0 = g / U19.5
constexpr double kMaxWindSpeed = 100;              // m/s: no sea state is fitted beyond it
constexpr double kMaxSpreadExponent = 1000;        // cos-2s: a swell narrower than ~2 degrees

// kd past which tanh(kd) is 1 and 2kd / sinh(2kd) is 0 in double.
constexpr double kDeepKd = 20;
// kd below which the series tanh(x) / x = 1 - x^2 / 3 is exact in double.
constexpr double kShallowKd = 1e-5;

// tanh(kd) / k, the squared phase speed over g; the limits taken before they divide.
double tanhOverK(double k, double depth) {
  double x = k * depth;
  if (!(x < kDeepKd)) return 1.0 / k;  // also d = infinity
  if (x < kShallowKd) return depth * (1.0 - x * x / 3.0);
  return std::tanh(x) / k;
}

// 2x / sinh(2x) for x = kd, 1 in shallow water, 0 in deep.
double twoKdOverSinh(double x) {
  if (!(x < kDeepKd)) return 0.0;
  double y = 2.0 * x;
  if (y < kShallowKd) return 1.0 - y * y / 6.0;
  return y / std::sinh(y);
}

// The Pierson-Moskowitz peak over g / U19.5: (4 beta / 5)^(1/4).
double piersonMoskowitzPeakCoefficient() { return std::pow(4.0 * kPiersonMoskowitzBeta / 5.0, 0.25); }

double wrapAngle(double theta) { return theta - 2.0 * kPi * std::nearbyint(theta / (2.0 * kPi)); }

double cos2s(double theta, double s) {
  double c = std::cos(0.5 * wrapAngle(theta));
  return cos2sNormalisation(s) * std::pow(std::max(c, 0.0), 2.0 * s);
}

bool finite(double x) { return std::isfinite(x); }

}  // namespace

std::optional<SettingError> validateSpectrum(const SpectrumSettings& s) {
  auto error = [](std::string p, std::string m) { return std::optional<SettingError>(SettingError{p, m}); };
  if (!finite(s.windSpeed) || s.windSpeed < 0 || s.windSpeed > kMaxWindSpeed)
    return error("wind_speed", "U10 " + numberText(s.windSpeed) + " m/s is outside [0, " + numberText(kMaxWindSpeed) + "]");
  if (!finite(s.windDirection)) return error("wind_direction", "must be a finite angle");
  if (std::isnan(s.fetch) || !(s.fetch > 0))
    return error("fetch", "fetch " + numberText(s.fetch) + " m must be greater than 0 (the sea needs open water to grow)");
  if (std::isnan(s.depth) || !(s.depth > 0))
    return error("depth", "depth " + numberText(s.depth) + " m must be greater than 0 (infinity for deep water)");
  if (!finite(s.gamma) || s.gamma < 1 || s.gamma > 20)
    return error("gamma", "peak enhancement " + numberText(s.gamma) + " is outside [1, 20]");
  if (!finite(s.phillipsAmplitude) || s.phillipsAmplitude < 0)
    return error("phillips_amplitude", "must be a finite number >= 0");
  if (!finite(s.phillipsSmallWave) || s.phillipsSmallWave < 0)
    return error("phillips_small_wave", "must be a finite length >= 0");
  if (!finite(s.swell.height) || s.swell.height < 0 || s.swell.height > 30)
    return error("swell_height", "Hs " + numberText(s.swell.height) + " m is outside [0, 30]");
  if (!finite(s.swell.period) || !(s.swell.period >= 1) || s.swell.period > 60)
    return error("swell_period", "Tp " + numberText(s.swell.period) + " s is outside [1, 60]");
  if (!finite(s.swell.direction)) return error("swell_direction", "must be a finite angle");
  if (!finite(s.swell.spread) || s.swell.spread < 0 || s.swell.spread > kMaxSpreadExponent)
    return error("swell_spread", "the cos-2s exponent " + numberText(s.swell.spread) + " is outside [0, " +
                                     numberText(kMaxSpreadExponent) + "]");
  return std::nullopt;
}

double angularFrequency(double k, double depth) {
  if (!(k > 0)) return 0.0;
  return std::sqrt(kGravity * k * k * tanhOverK(k, depth));
}

double groupVelocity(double k, double depth) {
  // omega = k c with c^2 = g tanh(kd) / k; d omega / dk = (c / 2)(1 + 2kd / sinh(2kd)),
  // which tends to sqrt(g d) as k -> 0 in finite depth (shallow-water waves do not disperse).
  double c = std::sqrt(kGravity * tanhOverK(std::max(k, 0.0), depth));
  if (!(k > 0)) c = std::isfinite(depth) ? std::sqrt(kGravity * depth) : std::numeric_limits<double>::infinity();
  return 0.5 * c * (1.0 + twoKdOverSinh(k * depth));
}

double tmaDepthFactor(double k, double depth) {
  double x = k * depth;
  if (!(x < kDeepKd)) return 1.0;
  double t = x < kShallowKd ? x * (1.0 - x * x / 3.0) : std::tanh(x);
  return t * t / (1.0 + twoKdOverSinh(x));
}

double fullyDevelopedFetch() {
  double peakU10 = piersonMoskowitzPeakCoefficient() / kU195OverU10;  // omega_p U10 / g
  return std::pow(22.0 / peakU10, 3.0);
}

JonswapParameters jonswapParameters(double windSpeed, double fetch) {
  JonswapParameters p;
  if (!(windSpeed > 0)) return p;  // a calm: alpha 0, no peak
  double chi = std::min(kGravity * fetch / (windSpeed * windSpeed), fullyDevelopedFetch());
  p.alpha = 0.076 * std::pow(chi, -0.22);
  p.omegaPeak = 22.0 * (kGravity / windSpeed) * std::pow(chi, -1.0 / 3.0);
  return p;
}

double piersonMoskowitzPeak(double windSpeed) {
  return piersonMoskowitzPeakCoefficient() * kGravity / (kU195OverU10 * windSpeed);
}

double piersonMoskowitzSpectrum(double omega, double windSpeed) {
  if (!(omega > 0) || !(windSpeed > 0)) return 0.0;
  double r = kGravity / (kU195OverU10 * windSpeed * omega);  // omega_0 / omega
  return kPiersonMoskowitzAlpha * kGravity * kGravity * std::pow(omega, -5.0) *
         std::exp(-kPiersonMoskowitzBeta * r * r * r * r);
}

double jonswapSpectrum(double omega, const JonswapParameters& p, double gamma) {
  if (!(omega > 0) || !(p.alpha > 0) || !(p.omegaPeak > 0)) return 0.0;
  double x = omega / p.omegaPeak;
  double sigma = x <= 1.0 ? 0.07 : 0.09;
  double r = std::exp(-(x - 1.0) * (x - 1.0) / (2.0 * sigma * sigma));
  double x4 = x * x * x * x;
  return p.alpha * kGravity * kGravity * std::pow(omega, -5.0) * std::exp(-1.25 / x4) * std::pow(gamma, r);
}

double swellSpectrum(double omega, double height, double omegaPeak) {
  if (!(omega > 0) || !(height > 0) || !(omegaPeak > 0)) return 0.0;
  // A omega^-5 exp(-5/4 (wp/w)^4) integrates to A / (5 wp^4): A = 5 wp^4 Hs^2 / 16.
  double x = omegaPeak / omega;
  double x4 = x * x * x * x;
  return (5.0 / 16.0) * height * height * x4 / omega * std::exp(-1.25 * x4);
}

double cos2sNormalisation(double s) {
  // The integral of cos^2s(theta / 2) over (-pi, pi] is 2 sqrt(pi) Gamma(s + 1/2) / Gamma(s + 1).
  return std::exp(std::lgamma(s + 1.0) - std::lgamma(s + 0.5)) / (2.0 * std::sqrt(kPi));
}

double mitsuyasuExponent(double omega, double omegaPeak, double windSpeed) {
  double sMax = 11.5 * std::pow(omegaPeak * windSpeed / kGravity, -2.5);
  double x = omega / omegaPeak;
  double s = x <= 1.0 ? sMax * std::pow(x, 5.0) : sMax * std::pow(x, -2.5);
  return std::clamp(s, 0.0, kMaxSpreadExponent);
}

double hasselmannExponent(double omega, double omegaPeak, double windSpeed) {
  double x = omega / omegaPeak;
  double s;
  if (x < 1.05) {
    s = 6.97 * std::pow(x, 4.06);
  } else {
    double inverseWaveAge = windSpeed * omegaPeak / kGravity;  // U / c_p, c_p = g / omega_p
    s = 9.77 * std::pow(x, -2.33 - 1.45 * (inverseWaveAge - 1.17));
  }
  return std::clamp(s, 0.0, kMaxSpreadExponent);
}

double directionalSpreading(Spreading model, double theta, double omega, double omegaPeak, double windSpeed) {
  switch (model) {
    case Spreading::Cos2: {
      double c = std::cos(theta);
      return c * c / kPi;
    }
    case Spreading::Mitsuyasu:
      return cos2s(theta, mitsuyasuExponent(omega, omegaPeak, windSpeed));
    case Spreading::Hasselmann:
      return cos2s(theta, hasselmannExponent(omega, omegaPeak, windSpeed));
  }
  return 0.0;
}

double spectrumPeak(const SpectrumSettings& s) {
  if (!(s.windSpeed > 0)) return 0.0;
  switch (s.model) {
    case SpectrumModel::Phillips: {
      // k^-3 exp(-1 / (k Lw)^2) peaks at k Lw = sqrt(2 / 3).
      double lw = s.windSpeed * s.windSpeed / kGravity;
      return angularFrequency(std::sqrt(2.0 / 3.0) / lw, s.depth);
    }
    case SpectrumModel::PiersonMoskowitz:
      return piersonMoskowitzPeak(s.windSpeed);
    case SpectrumModel::Jonswap:
    case SpectrumModel::Tma:
      return jonswapParameters(s.windSpeed, s.fetch).omegaPeak;
  }
  return 0.0;
}

double windSeaFrequencySpectrum(const SpectrumSettings& s, double k) {
  double omega = angularFrequency(k, s.depth);
  switch (s.model) {
    case SpectrumModel::Phillips: {
      if (!(k > 0) || !(s.windSpeed > 0)) return 0.0;
      double kl = k * s.windSpeed * s.windSpeed / kGravity;
      double e = kPi * s.phillipsAmplitude * std::exp(-1.0 / (kl * kl)) *
                 std::exp(-k * k * s.phillipsSmallWave * s.phillipsSmallWave) / (k * k * k);
      return e / groupVelocity(k, s.depth);  // E(k) = S(omega) d omega / dk
    }
    case SpectrumModel::PiersonMoskowitz:
      return piersonMoskowitzSpectrum(omega, s.windSpeed);
    case SpectrumModel::Jonswap:
      return jonswapSpectrum(omega, jonswapParameters(s.windSpeed, s.fetch), s.gamma);
    case SpectrumModel::Tma:
      return jonswapSpectrum(omega, jonswapParameters(s.windSpeed, s.fetch), s.gamma) * tmaDepthFactor(k, s.depth);
  }
  return 0.0;
}

namespace {

// E_wind(k) and E_swell(k), m^3.
struct SpectrumParts {
  double wind = 0, swell = 0;
};

SpectrumParts wavenumberParts(const SpectrumSettings& s, double k) {
  SpectrumParts e;
  if (!(k > 0)) return e;
  double cg = groupVelocity(k, s.depth);
  e.wind = windSeaFrequencySpectrum(s, k) * cg;
  double swellPeak = 2.0 * kPi / s.swell.period;
  e.swell = swellSpectrum(angularFrequency(k, s.depth), s.swell.height, swellPeak) * cg;
  if (s.model == SpectrumModel::Tma) e.swell *= tmaDepthFactor(k, s.depth);
  return e;
}

}  // namespace

double omnidirectionalSpectrum(const SpectrumSettings& s, double k) {
  SpectrumParts e = wavenumberParts(s, k);
  return e.wind + e.swell;
}

double directionalSpectrum(const SpectrumSettings& s, double kx, double kz) {
  double k = std::hypot(kx, kz);
  SpectrumParts e = wavenumberParts(s, k);
  double f = 0;
  double heading = std::atan2(kz, kx);
  if (e.wind > 0) {
    double omega = angularFrequency(k, s.depth);
    f += e.wind * directionalSpreading(s.spreading, heading - s.windDirection, omega, spectrumPeak(s), s.windSpeed);
  }
  if (e.swell > 0) f += e.swell * cos2s(heading - s.swell.direction, s.swell.spread);
  return f / k;  // polar to Cartesian: dkx dkz = k dk dtheta
}

std::string numberText(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

}  // namespace wg::ocean
