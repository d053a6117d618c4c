// The spectral ocean's double reference (core/ocean_fft_reference.h): cascade validation
// and bands, initial amplitudes, evolution, and the inverse transforms with FFTW.
#include "core/ocean_fft_reference.h"

#include <fftw3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

#include "core/ocean_random.h"

namespace wg::ocean {
namespace {

bool powerOfTwo(int n) { return n > 0 && (n & (n - 1)) == 0; }

double largestAxialWavenumber(int n, double tileLength) { return (n / 2 - 1) * 2.0 * kPi / tileLength; }
double smallestWavenumber(double tileLength) { return 2.0 * kPi / tileLength; }

constexpr double kTwoTo32 = 4294967296.0;

// The multiple of 2 pi / T nearest to omega. A wave faster than (2^32 - 1) 2 pi / T
// (4e5 rad/s: a grid spacing under a micrometre) keeps that largest index.
std::uint32_t frequencyIndex(double omega) {
  return static_cast<std::uint32_t>(std::min(std::nearbyint(omega * kLoopPeriod / (2.0 * kPi)), kTwoTo32 - 1.0));
}

// One FFTW plan for N x N backward complex transforms with its own arrays. FFTW's planner
// is not thread-safe, so making and destroying plans takes a lock; executing does not.
std::mutex& plannerLock() {
  static std::mutex m;
  return m;
}

class InverseFft {
 public:
  explicit InverseFft(int n) : n_(n) {
    size_t count = static_cast<size_t>(n) * n;
    in_ = fftw_alloc_complex(count);
    out_ = fftw_alloc_complex(count);
    std::lock_guard<std::mutex> lock(plannerLock());
    // FFTW_ESTIMATE picks the same algorithm every run (FFTW_MEASURE times candidates), so
    // the reference's digits do not depend on the machine's load.
    plan_ = fftw_plan_dft_2d(n, n, in_, out_, FFTW_BACKWARD, FFTW_ESTIMATE);
  }
  ~InverseFft() {
    {
      std::lock_guard<std::mutex> lock(plannerLock());
      fftw_destroy_plan(plan_);
    }
    fftw_free(in_);
    fftw_free(out_);
  }
  InverseFft(const InverseFft&) = delete;
  InverseFft& operator=(const InverseFft&) = delete;

  // The real part of sum over k of spectrum(k) factor(k) exp(i k.x); the spectra given
  // here are Hermitian, so the imaginary part is rounding only.
  template <class Factor>
  std::vector<double> transform(const std::vector<std::complex<double>>& spectrum, Factor factor) {
    size_t count = static_cast<size_t>(n_) * n_;
    for (size_t i = 0; i < count; ++i) {
      std::complex<double> v = spectrum[i] * factor(i);
      in_[i][0] = v.real();
      in_[i][1] = v.imag();
    }
    fftw_execute(plan_);
    std::vector<double> field(count);
    for (size_t i = 0; i < count; ++i) field[i] = out_[i][0];
    return field;
  }

 private:
  int n_;
  fftw_complex* in_ = nullptr;
  fftw_complex* out_ = nullptr;
  fftw_plan plan_ = nullptr;
};

}  // namespace

std::optional<SettingError> validateCascades(const CascadeSettings& c) {
  auto error = [](std::string p, std::string m) { return std::optional<SettingError>(SettingError{p, m}); };
  if (!powerOfTwo(c.resolution) || c.resolution < kMinResolution || c.resolution > kMaxResolution)
    return error("resolution", std::to_string(c.resolution) + " is not a power of two in [" +
                                   std::to_string(kMinResolution) + ", " + std::to_string(kMaxResolution) + "]");
  if (c.tileLengths.empty() || c.tileLengths.size() > static_cast<size_t>(kMaxCascades))
    return error("tile_lengths", "lists " + std::to_string(c.tileLengths.size()) + " cascades; 1 to " +
                                     std::to_string(kMaxCascades) + " are allowed");
  if (!c.sizes.empty() && c.sizes.size() != c.tileLengths.size())
    return error("cascade_sizes", "lists " + std::to_string(c.sizes.size()) + " sizes for " +
                                      std::to_string(c.tileLengths.size()) +
                                      " cascades (tile_lengths): one a cascade, or none for fft_size everywhere");
  for (size_t i = 0; i < c.sizes.size(); ++i)
    if (!powerOfTwo(c.sizes[i]) || c.sizes[i] < kMinCascadeResolution || c.sizes[i] > kMaxResolution)
      return error("cascade_sizes", "cascade " + std::to_string(i) + ": " + std::to_string(c.sizes[i]) +
                                        " is not a power of two in [" + std::to_string(kMinCascadeResolution) + ", " +
                                        std::to_string(kMaxResolution) + "]");
  for (size_t i = 0; i < c.tileLengths.size(); ++i) {
    double l = c.tileLengths[i];
    std::string where = "cascade " + std::to_string(i) + ": ";
    if (!std::isfinite(l) || !(l > 0))
      return error("tile_lengths", where + "tile length " + numberText(l) + " m must be a finite number greater than 0");
    if (i == 0) continue;
    double previous = c.tileLengths[i - 1];
    if (l == previous)
      return error("tile_lengths", where + "tile length " + numberText(l) + " m repeats cascade " + std::to_string(i - 1) +
                                       "'s: two cascades would share one band of wavenumbers");
    if (l > previous)
      return error("tile_lengths", where + "tile length " + numberText(l) + " m is longer than cascade " +
                                       std::to_string(i - 1) + "'s " + numberText(previous) +
                                       " m: list the cascades from the longest tile to the shortest");
    // The finer grid's first bin must lie below the coarser grid's last at the smallest
    // resolution (the bands do not move with it: cascadeBands), or the wavenumbers between
    // them belong to neither.
    if (!(smallestWavenumber(l) < largestAxialWavenumber(kMinResolution, previous)))
      return error("tile_lengths", where + "tile length " + numberText(l) + " m is more than " +
                                       std::to_string(kMinResolution / 2 - 1) + " times shorter than " +
                                       numberText(previous) + " m: the wavenumbers between the two grids would be lost");
  }
  if (!std::isfinite(c.choppiness) || c.choppiness < 0 || c.choppiness > kMaxChoppiness)
    return error("choppiness", numberText(c.choppiness) + " is outside [0, " + numberText(kMaxChoppiness) + "]");
  if (c.seed < 0 || c.seed > static_cast<std::int64_t>(UINT32_MAX))
    return error("seed", std::to_string(c.seed) + " is outside the 32-bit range [0, 4294967295]");
  return std::nullopt;
}

std::vector<WavenumberBand> cascadeBands(const CascadeSettings& c) {
  size_t count = c.tileLengths.size();
  std::vector<WavenumberBand> bands(count);
  for (size_t i = 0; i < count; ++i) {
    bands[i].low = i == 0 ? 0.0 : bands[i - 1].high;
    bands[i].high = i + 1 == count ? std::numeric_limits<double>::infinity()
                                   : std::sqrt(largestAxialWavenumber(kMinResolution, c.tileLengths[i]) *
                                               smallestWavenumber(c.tileLengths[i + 1]));
  }
  return bands;
}

int cascadeResolution(const CascadeSettings& c, size_t index) {
  // fft_size caps every cascade, so that the two knobs compose: lowering fft_size lowers a
  // cascade whose own size is larger, and never does nothing.
  return c.sizes.empty() ? c.resolution : std::min(c.resolution, c.sizes.at(index));
}

int signedIndex(int m, int resolution) { return m < resolution / 2 ? m : m - resolution; }

OceanCascade emptyCascade(int resolution, double tileLength, double depth) {
  OceanCascade cascade;
  cascade.resolution = resolution;
  cascade.tileLength = tileLength;
  size_t count = static_cast<size_t>(resolution) * resolution;
  cascade.h0.assign(count, {0.0, 0.0});
  cascade.frequency.assign(count, 0);
  cascade.binVariance.assign(count, 0.0);
  double dk = 2.0 * kPi / tileLength;
  for (int iz = 0; iz < resolution; ++iz)
    for (int ix = 0; ix < resolution; ++ix) {
      double k = std::hypot(dk * signedIndex(ix, resolution), dk * signedIndex(iz, resolution));
      cascade.frequency[static_cast<size_t>(iz) * resolution + ix] = frequencyIndex(angularFrequency(k, depth));
    }
  return cascade;
}

double bandEnergyHeld(const SpectrumSettings& s, const CascadeSettings& c, int index) {
  if (auto e = validateSpectrum(s)) throw std::invalid_argument(e->parameter + ": " + e->message);
  if (auto e = validateCascades(c)) throw std::invalid_argument(e->parameter + ": " + e->message);
  if (index < 0 || index >= static_cast<int>(c.tileLengths.size()))
    throw std::invalid_argument("cascade " + std::to_string(index) + " does not exist");
  const int full = kMaxResolution, n = cascadeResolution(c, static_cast<size_t>(index));
  const WavenumberBand band = cascadeBands(c)[static_cast<size_t>(index)];
  const double dk = 2.0 * kPi / c.tileLengths[static_cast<size_t>(index)];
  double all = 0, held = 0;
  // The bins initialCascade fills on the largest grid, and of them those the cascade's own
  // grid has (signed indices within (-n/2, n/2): its Nyquist row and column stay empty).
  for (int sz = -full / 2 + 1; sz < full / 2; ++sz)
    for (int sx = -full / 2 + 1; sx < full / 2; ++sx) {
      const double kx = dk * sx, kz = dk * sz, k = std::hypot(kx, kz);
      if (!(k > 0) || k < band.low || !(k < band.high)) continue;
      const double variance = directionalSpectrum(s, kx, kz) * dk * dk;
      all += variance;
      if (std::abs(sx) < n / 2 && std::abs(sz) < n / 2) held += variance;
    }
  return all > 0 ? held / all : 1.0;
}

OceanCascade initialCascade(const SpectrumSettings& s, const CascadeSettings& c, int index) {
  if (auto e = validateSpectrum(s)) throw std::invalid_argument(e->parameter + ": " + e->message);
  if (auto e = validateCascades(c)) throw std::invalid_argument(e->parameter + ": " + e->message);
  if (index < 0 || index >= static_cast<int>(c.tileLengths.size()))
    throw std::invalid_argument("cascade " + std::to_string(index) + " does not exist");
  int n = cascadeResolution(c, static_cast<size_t>(index));
  OceanCascade cascade = emptyCascade(n, c.tileLengths[static_cast<size_t>(index)], s.depth);
  WavenumberBand band = cascadeBands(c)[static_cast<size_t>(index)];
  double dk = 2.0 * kPi / cascade.tileLength;
  auto seed = static_cast<std::uint32_t>(c.seed);
  for (int iz = 0; iz < n; ++iz)
    for (int ix = 0; ix < n; ++ix) {
      if (ix == n / 2 || iz == n / 2) continue;  // the Nyquist row and column: no mirror
      double kx = dk * signedIndex(ix, n), kz = dk * signedIndex(iz, n);
      double k = std::hypot(kx, kz);
      if (!(k > 0) || k < band.low || !(k < band.high)) continue;
      size_t i = static_cast<size_t>(iz) * n + ix;
      cascade.binVariance[i] = directionalSpectrum(s, kx, kz) * dk * dk;
      // Drawn by the signed wavenumber index (two's complement), so a lower resolution keeps
      // the same waves and only drops the shortest (the resolution knob approximates one sea).
      GaussianPair g = binGaussians(static_cast<std::uint32_t>(index), static_cast<std::uint32_t>(signedIndex(ix, n)),
                                    static_cast<std::uint32_t>(signedIndex(iz, n)), seed);
      cascade.h0[i] = std::complex<double>(g.real, g.imag) * (0.5 * std::sqrt(cascade.binVariance[i]));
    }
  return cascade;
}

std::uint32_t loopFraction(double time) {
  if (!std::isfinite(time)) return 0;  // a clock that is not a number stands still at 0
  double loops = time / kLoopPeriod;  // exact: T is a power of two
  double fraction = loops - std::floor(loops);
  // fraction 2^32 is exact too; the floor of a value in [0, 2^32) fits.
  return static_cast<std::uint32_t>(std::min(std::floor(fraction * kTwoTo32), kTwoTo32 - 1.0));
}

double angularFrequencyOf(std::uint32_t frequency) { return frequency * (2.0 * kPi / kLoopPeriod); }

double phaseTurns(std::uint32_t frequency, std::uint32_t tau) {
  std::uint32_t product = frequency * tau;  // modulo 2^32, as GLSL's uint product
  return product / kTwoTo32;
}

std::vector<std::complex<double>> evolveSpectrum(const OceanCascade& cascade, double time) {
  int n = cascade.resolution;
  std::uint32_t tau = loopFraction(time);
  std::vector<std::complex<double>> h(cascade.h0.size());
  for (int iz = 0; iz < n; ++iz)
    for (int ix = 0; ix < n; ++ix) {
      size_t i = static_cast<size_t>(iz) * n + ix;
      size_t mirror = static_cast<size_t>((n - iz) % n) * n + static_cast<size_t>((n - ix) % n);
      double phase = 2.0 * kPi * phaseTurns(cascade.frequency[i], tau);
      std::complex<double> turn(std::cos(phase), std::sin(phase));
      h[i] = cascade.h0[i] * std::conj(turn) + std::conj(cascade.h0[mirror]) * turn;
    }
  return h;
}

std::vector<double> oceanHeight(const OceanCascade& cascade, double time) {
  InverseFft fft(cascade.resolution);
  return fft.transform(evolveSpectrum(cascade, time), [](size_t) { return std::complex<double>(1.0, 0.0); });
}

OceanFields oceanFields(const OceanCascade& cascade, double time, double choppiness) {
  int n = cascade.resolution;
  double dk = 2.0 * kPi / cascade.tileLength;
  size_t count = static_cast<size_t>(n) * n;
  std::vector<double> kx(count), kz(count), k(count);
  for (size_t i = 0; i < count; ++i) {
    kx[i] = dk * signedIndex(static_cast<int>(i % n), n);
    kz[i] = dk * signedIndex(static_cast<int>(i / n), n);
    k[i] = std::hypot(kx[i], kz[i]);
  }
  auto unitOrZero = [&](const std::vector<double>& c, size_t i) { return k[i] > 0 ? c[i] / k[i] : 0.0; };
  const std::complex<double> I(0.0, 1.0);

  std::vector<std::complex<double>> h = evolveSpectrum(cascade, time);
  InverseFft fft(n);
  OceanFields f;
  f.resolution = n;
  f.tileLength = cascade.tileLength;
  f.height = fft.transform(h, [](size_t) { return std::complex<double>(1.0, 0.0); });
  f.displacementX = fft.transform(h, [&](size_t i) { return I * unitOrZero(kx, i); });
  f.displacementZ = fft.transform(h, [&](size_t i) { return I * unitOrZero(kz, i); });
  f.slopeX = fft.transform(h, [&](size_t i) { return I * kx[i]; });
  f.slopeZ = fft.transform(h, [&](size_t i) { return I * kz[i]; });
  // d/dx of i kx/k h~ exp(i k.x) is -kx^2/k h~ exp(i k.x).
  f.dDxdx = fft.transform(h, [&](size_t i) { return std::complex<double>(-kx[i] * unitOrZero(kx, i), 0.0); });
  f.dDzdz = fft.transform(h, [&](size_t i) { return std::complex<double>(-kz[i] * unitOrZero(kz, i), 0.0); });
  f.dDxdz = fft.transform(h, [&](size_t i) { return std::complex<double>(-kx[i] * unitOrZero(kz, i), 0.0); });
  f.jacobian.resize(count);
  for (size_t i = 0; i < count; ++i)
    f.jacobian[i] = (1.0 + choppiness * f.dDxdx[i]) * (1.0 + choppiness * f.dDzdz[i]) -
                    choppiness * choppiness * f.dDxdz[i] * f.dDxdz[i];
  return f;
}

std::vector<double> oceanJacobian(const OceanCascade& cascade, double time, double choppiness) {
  int n = cascade.resolution;
  double dk = 2.0 * kPi / cascade.tileLength;
  std::vector<std::complex<double>> h = evolveSpectrum(cascade, time);
  auto wavenumber = [&](size_t i) {
    double kx = dk * signedIndex(static_cast<int>(i % n), n), kz = dk * signedIndex(static_cast<int>(i / n), n);
    return std::array<double, 3>{kx, kz, std::hypot(kx, kz)};
  };
  auto derivative = [&](int a, int b) {
    return [&, a, b](size_t i) {
      auto k = wavenumber(i);
      // As oceanFields rounds it: -k_a (k_b / k).
      return std::complex<double>(-k[a] * (k[2] > 0 ? k[b] / k[2] : 0.0), 0.0);
    };
  };
  InverseFft fft(n);
  std::vector<double> xx = fft.transform(h, derivative(0, 0));
  std::vector<double> zz = fft.transform(h, derivative(1, 1));
  std::vector<double> xz = fft.transform(h, derivative(0, 1));
  std::vector<double> j(xx.size());
  for (size_t i = 0; i < j.size(); ++i)
    j[i] = (1.0 + choppiness * xx[i]) * (1.0 + choppiness * zz[i]) - choppiness * choppiness * xz[i] * xz[i];
  return j;
}

}  // namespace wg::ocean
