#pragma once
// The spectral ocean's double-precision reference (Tessendorf, "Simulating Ocean Water",
// 2001): initial amplitudes h0(k) drawn from a spectrum (core/ocean_spectrum.h) with
// counter-based Gaussian numbers (core/ocean_random.h), evolved in time with the
// dispersion relation, and transformed to the surface's fields by inverse FFT (FFTW).
//
// The surface is h(x, t) = sum over k of h~(k, t) exp(i k.x), x on an N x N grid of
// spacing L / N, k = 2 pi / L (mx, mz) with mx, mz in [-N/2, N/2), and
//   h~(k, t) = h0(k) exp(-i omega t) + conj(h0(-k)) exp(i omega t).
// The sign of omega t is Tessendorf's with t -> -t, so that h0(k) is the wave travelling
// along k (the spreading's direction).
//
// Phases are exact integers: each bin's frequency is the multiple n(k) of 2 pi / T of the
// loop period T = 2^16 s nearest to the dispersion's omega (a relative error of at most
// pi / (T omega), 5e-5 at 1 rad/s), and time enters as the 32-bit fraction of a loop,
// tau = floor(frac(t / T) 2^32) (a time step of T / 2^32 = 15 us). The phase in turns is
// then (n tau mod 2^32) / 2^32, the same 32 bits in double here and in a GPU's uint
// arithmetic at any t: 1e6 s is as exact as 1 s, and the sea repeats every 18.2 hours.
//
// Amplitudes: h0(k) = (xi_r + i xi_i) sqrt(F(k) dk^2) / 2 with xi standard normal, so that
// a travelling wave's variance 2 E|h0(k)|^2 is F(k) dk^2 and the surface's variance is the
// spectrum's integral m0 (Parseval). Tessendorf's 1 / sqrt(2) without the 1 / 2 would
// count each wave twice (once as h0(k), once as conj(h0(-k)) of its mirror).
//
// The Nyquist row and column (mx or mz = -N/2) have no mirror of their own and are left
// empty; the mean (k = 0) is 0. h0 is the canonical double value: a GPU implementation
// uploads it rounded to float32 rather than redrawing it, so CPU and GPU start from the
// same amplitudes bit for bit.
#include <complex>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/ocean_spectrum.h"

namespace wg::ocean {

inline constexpr int kMinResolution = 64;  // fft_size's least; the cascades' bands are drawn at it
inline constexpr int kMaxResolution = 512;
// A cascade's own size (cascade_sizes) may be smaller than fft_size's least: a long tile's
// band ends near its 12th bin (cascadeBands), which a 32^2 grid already holds.
inline constexpr int kMinCascadeResolution = 16;
inline constexpr int kMaxCascades = 4;
inline constexpr double kMaxChoppiness = 4;
inline constexpr double kLoopPeriod = 65536;  // s, T: the bins' frequencies are multiples of 2 pi / T

struct CascadeSettings {
  int resolution = 256;                     // N: a power of two in [64, 512]
  std::vector<double> tileLengths{1000.0};  // metres, 1 to 4, strictly decreasing
  // Each cascade's own N (cascade_sizes), a power of two in [16, 512], one per tile, capped
  // by `resolution`; empty: every cascade at `resolution`. A long tile's band holds only its
  // first dozen bins, so a small grid carries the same waves (cascadeResolution reads it).
  std::vector<int> sizes;
  double choppiness = 1;                    // lambda in [0, 4]; positive sharpens crests
  std::int64_t seed = 0;                    // [0, 2^32)
};
std::optional<SettingError> validateCascades(const CascadeSettings& c);
// Cascade `index`'s N: the smaller of its entry of `sizes` and `resolution` (fft_size caps
// every cascade), or `resolution` when sizes is empty.
int cascadeResolution(const CascadeSettings& c, size_t index);

// Each cascade owns the wavenumbers |k| in [low, high): the coarsest from 0, the finest to
// infinity (its whole grid), and between cascade i and i + 1 the geometric mean of i's
// largest axial wavenumber at fft_size's smallest, (kMinResolution/2 - 1) 2 pi / L_i,
// and i + 1's smallest 2 pi / L_(i+1). No bin is counted by two cascades, and no
// wavenumber between the grids is lost. The bands depend on no resolution (neither
// fft_size nor cascade_sizes), so that lowering one (a quality knob) drops only the waves
// beyond the smaller grid's Nyquist and keeps one sea, instead of moving waves between
// cascades (where other draws make them). A cascade smaller than 64^2 holds its band only
// as far as its own grid reaches (bandEnergyHeld measures what it drops).
struct WavenumberBand {
  double low = 0, high = 0;  // rad/m
};
std::vector<WavenumberBand> cascadeBands(const CascadeSettings& c);

// The signed wavenumber index of FFT index m in [0, N): m below N/2, m - N from N/2 on.
int signedIndex(int m, int resolution);

struct OceanCascade {
  int resolution = 0;
  double tileLength = 0;
  std::vector<std::complex<double>> h0;  // metres, index iz * N + ix
  std::vector<std::uint32_t> frequency;  // n(k): omega = n 2 pi / T (dispersion at the settings' depth)
  std::vector<double> binVariance;       // F(k) dk^2 (m^2) for the bins the cascade owns, else 0
};
// The share of cascade `index`'s band variance (the spectrum's integral over the bins it
// owns on a 512^2 grid, in double) that its own grid holds: 1 where cascade_sizes drops
// nothing. The double reference's measure of what a smaller grid costs in waves.
double bandEnergyHeld(const SpectrumSettings& s, const CascadeSettings& c, int index);

// A cascade with no waves: its grid and each bin's frequency at `depth`.
OceanCascade emptyCascade(int resolution, double tileLength, double depth);
// Cascade `index` of valid settings (std::invalid_argument otherwise).
OceanCascade initialCascade(const SpectrumSettings& s, const CascadeSettings& c, int index);

// tau: the fraction of the loop at time t, in units of 2^-32 of a loop (0 for a time that
// is not finite).
std::uint32_t loopFraction(double time);
// A bin's frequency in rad/s, n 2 pi / T.
double angularFrequencyOf(std::uint32_t frequency);
// A bin's phase in turns, [0, 1): (n tau mod 2^32) / 2^32.
double phaseTurns(std::uint32_t frequency, std::uint32_t tau);

// h~(k, t) for every bin, index iz * N + ix.
std::vector<std::complex<double>> evolveSpectrum(const OceanCascade& cascade, double time);

// The surface's fields on the N x N grid, index jz * N + jx, at x = jx L / N, z = jz L / N.
// D is the horizontal displacement per unit choppiness, sum of i k/|k| h~ exp(i k.x): a
// point of the still surface moves to x + lambda Dx, z + lambda Dz. (Tessendorf's eq. 29
// has -i, with which a positive lambda would sharpen the troughs instead of the crests.)
struct OceanFields {
  int resolution = 0;
  double tileLength = 0;
  std::vector<double> height;                      // h, m
  std::vector<double> displacementX, displacementZ;  // Dx, Dz, m
  std::vector<double> slopeX, slopeZ;               // dh/dx, dh/dz
  std::vector<double> dDxdx, dDzdz, dDxdz;          // derivatives of D
  std::vector<double> jacobian;  // (1 + l dDx/dx)(1 + l dDz/dz) - l^2 (dDx/dz)^2; < 0 where the surface folds
};
OceanFields oceanFields(const OceanCascade& cascade, double time, double choppiness);
// The Jacobian alone (three transforms instead of eight), as oceanFields(...).jacobian.
std::vector<double> oceanJacobian(const OceanCascade& cascade, double time, double choppiness);
// The height alone (one transform instead of eight), as oceanFields(...).height.
std::vector<double> oceanHeight(const OceanCascade& cascade, double time);

}  // namespace wg::ocean
