#pragma once
// Wind-wave spectra, directional spreading and the dispersion relation of the spectral
// ocean, in double. This is the physics the FFT reference (core/ocean_fft_reference.h)
// samples onto its grids; docs/ocean.md states the model, its units and its sources.
//
// Conventions (SI throughout):
//   - S(omega) is the one-sided frequency spectrum of the surface elevation, m^2 s / rad,
//     so the elevation variance is m0 = integral of S over omega in (0, inf).
//   - F(kx, kz) is the directional wavenumber spectrum, m^4: m0 = integral of F over the
//     (kx, kz) plane. F = S(omega(k)) D(theta) (d omega / dk) / k, the change of variables
//     from (omega, theta) to the Cartesian wavenumber plane (dkx dkz = k dk dtheta).
//   - D(theta) integrates to 1 over theta in (-pi, pi]; theta is measured from the wind's
//     direction, and F at k is the energy of waves travelling along k.
//   - The wind speed is U10, the mean wind 10 m above the sea. Pierson-Moskowitz is defined
//     on U19.5 (the weather ships' anemometer height) and is given U19.5 = 1.026 U10.
#include <limits>
#include <optional>
#include <string>

namespace wg::ocean {

inline constexpr double kGravity = 9.81;  // m/s^2, the value the Gerstner nodes use too
inline constexpr double kPi = 3.14159265358979323846;

// U19.5 / U10 for a neutral logarithmic wind profile with drag coefficient 1.3e-3
// (Stewart, Introduction to Physical Oceanography, eq. 16.29).
inline constexpr double kU195OverU10 = 1.026;

enum class SpectrumModel {
  Phillips,           // Tessendorf 2001: A exp(-1/(k Lw)^2) / k^4, Lw = U^2 / g
  PiersonMoskowitz,   // fully developed sea (1964)
  Jonswap,            // fetch-limited sea (Hasselmann et al. 1973)
  Tma,                // JONSWAP times Kitaigorodskii's depth factor (Bouws et al. 1985)
};

enum class Spreading {
  Cos2,        // cos^2(theta) / pi: Phillips' |k.w|^2, waves both with and against the wind
  Mitsuyasu,   // cos-2s, s from Mitsuyasu et al. 1975
  Hasselmann,  // cos-2s, s from Hasselmann et al. 1980
};

// A swell from far away: a Pierson-Moskowitz-shaped spectrum scaled to its significant
// height, travelling in its own direction with a fixed cos-2s spread. Height 0: none.
struct Swell {
  double height = 0;     // significant wave height Hs of the swell alone, m
  double period = 10;    // peak period Tp, s
  double direction = 0;  // radians from +x toward +z, the way the swell travels
  double spread = 20;    // the cos-2s exponent s (larger: narrower)
};

struct SpectrumSettings {
  SpectrumModel model = SpectrumModel::Jonswap;
  double windSpeed = 10;       // U10, m/s; 0 is a calm (an empty spectrum)
  double windDirection = 0;    // radians from +x toward +z, the way the wind blows
  double fetch = 100e3;        // m, JONSWAP and TMA; past gF/U^2 ~ 1.7e4 the sea is fully developed
  double depth = std::numeric_limits<double>::infinity();  // m; infinity is deep water
  double gamma = 3.3;          // JONSWAP peak enhancement
  double phillipsAmplitude = 1e-3;  // Phillips' A (dimensionless)
  double phillipsSmallWave = 0;     // Phillips' suppression length l, m (exp(-k^2 l^2)); 0: none
  Spreading spreading = Spreading::Hasselmann;
  Swell swell;
};

// Why a setting is meaningless: the field's name as a node would spell it, and a sentence.
struct SettingError {
  std::string parameter;
  std::string message;
};
std::optional<SettingError> validateSpectrum(const SpectrumSettings& s);

// Dispersion: omega^2 = g k tanh(k d), d = infinity for deep water. Finite for every
// k >= 0 and d > 0, including d far below a wavelength (omega -> k sqrt(g d)).
double angularFrequency(double k, double depth);
// The group velocity d omega / dk (m/s).
double groupVelocity(double k, double depth);
// Kitaigorodskii's depth factor: the ratio of the k^-3 saturation range's frequency
// spectrum at depth d to that in deep water, tanh^2(kd) / (1 + 2kd / sinh(2kd)); 1 in deep
// water, (omega_h)^2 / 2 in shallow (omega_h = omega sqrt(d / g)).
double tmaDepthFactor(double k, double depth);

// The fetch laws of JONSWAP: alpha = 0.076 (U^2 / (F g))^0.22, omega_p = 22 (g^2 / (U F))^(1/3),
// with the dimensionless fetch gF/U^2 capped where omega_p falls to Pierson-Moskowitz's.
struct JonswapParameters {
  double alpha = 0;
  double omegaPeak = 0;
};
JonswapParameters jonswapParameters(double windSpeed, double fetch);
// The largest dimensionless fetch gF/U10^2 the fetch laws are applied to (the fully developed sea).
double fullyDevelopedFetch();

// One-sided frequency spectra, m^2 s / rad. Zero for omega <= 0.
double piersonMoskowitzSpectrum(double omega, double windSpeed);  // windSpeed is U10
double piersonMoskowitzPeak(double windSpeed);                    // 0.877 g / U19.5, rad/s
double jonswapSpectrum(double omega, const JonswapParameters& p, double gamma);
// Pierson-Moskowitz shape with peak omega_p and variance Hs^2 / 16 exactly.
double swellSpectrum(double omega, double height, double omegaPeak);

// The cos-2s normalisation Q(s), so that Q |cos(theta/2)|^(2s) integrates to 1.
double cos2sNormalisation(double s);
// The spreading exponent s of Mitsuyasu (1975) and Hasselmann (1980) at omega.
double mitsuyasuExponent(double omega, double omegaPeak, double windSpeed);
double hasselmannExponent(double omega, double omegaPeak, double windSpeed);
// D(theta) of a model at omega, theta measured from the wind direction, any real angle.
double directionalSpreading(Spreading model, double theta, double omega, double omegaPeak, double windSpeed);

// The peak frequency that drives the spreading exponents (rad/s): the model's spectral peak.
double spectrumPeak(const SpectrumSettings& s);
// The frequency spectrum of the wind sea alone at wavenumber k (TMA's factor needs k).
double windSeaFrequencySpectrum(const SpectrumSettings& s, double k);
// The omnidirectional wavenumber spectrum E(k) (m^3), wind sea and swell:
// m0 = integral of E over k in (0, inf).
double omnidirectionalSpectrum(const SpectrumSettings& s, double k);
// F(kx, kz), m^4. Zero at k = 0.
double directionalSpectrum(const SpectrumSettings& s, double kx, double kz);

// A value in an error message: six significant digits ("0.0001", "1e+06").
std::string numberText(double x);

}  // namespace wg::ocean
