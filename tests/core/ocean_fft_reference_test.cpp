// The spectral ocean's FFT reference (core/ocean_fft_reference.h) against values that do
// not come from the FFT: the spectrum's variance m0 integrated here (Parseval), Pierson and
// Moskowitz's Hs = 0.209 U19.5^2 / g, the period 2 pi / sqrt(g k tanh(kd)) of one bin
// written out, and the closed form of one wave's displacement, slopes and Jacobian.
#include <cmath>
#include <complex>
#include <cstdio>
#include <functional>

#include <gtest/gtest.h>

#include "core/ocean_fft_reference.h"
#include "ocean_test_support.h"
#include "core/ocean_random.h"

namespace wg::ocean {
namespace {

using namespace test_support;

constexpr double kEpsilon = 2.220446049250313e-16;


// The integral of E(k) over [a, b] on a logarithmic grid.
double integrateWavenumbers(const SpectrumSettings& s, double a, double b) {
  return simpson([&](double u) { return omnidirectionalSpectrum(s, std::exp(u)) * std::exp(u); }, std::log(a),
                 std::log(b), 40000);
}

double meanSquare(const std::vector<double>& v) {
  double sum = 0;
  for (double x : v) sum += x * x;
  return sum / static_cast<double>(v.size());
}

TEST(OceanRandom, CounterBasedGaussiansAreReproducible) {
  // Values from an independent implementation of the same integer steps (Python, whose
  // integers do not wrap: every product is reduced mod 2^32 by hand).
  auto h = pcg4d({0, 0, 0, 0});
  EXPECT_EQ(h[0], 251852841u);
  EXPECT_EQ(h[1], 760645481u);
  EXPECT_EQ(h[2], 850445371u);
  EXPECT_EQ(h[3], 3542436074u);
  struct Case {
    std::uint32_t cascade, ix, iz, seed;
    double real, imag;
  };
  for (const Case& c : {Case{0, 0, 0, 0, 1.0531739436373029, 2.1362427697024384},
                        Case{3, 1, 2, 4, 1.6458921176345922, -0.6311872731744596},
                        Case{2, 255, 17, 4294967295u, -1.5524794848063093, -0.6442267156212047}}) {
    GaussianPair p = binGaussians(c.cascade, c.ix, c.iz, c.seed);
    EXPECT_NEAR(p.real, c.real, 4 * kEpsilon * std::abs(c.real));
    EXPECT_NEAR(p.imag, c.imag, 4 * kEpsilon * std::abs(c.imag));
  }
  // 2^16 draws: mean 0 and variance 1 within 5 standard errors (1 / sqrt(n) and
  // sqrt(2 / n)), the real and imaginary parts uncorrelated within 5 / sqrt(n).
  double sum = 0, sumSquares = 0, cross = 0;
  const int n = 1 << 16;
  for (int i = 0; i < n / 2; ++i) {
    GaussianPair p = binGaussians(1, static_cast<std::uint32_t>(i % 256), static_cast<std::uint32_t>(i / 256), 7);
    sum += p.real + p.imag;
    sumSquares += p.real * p.real + p.imag * p.imag;
    cross += p.real * p.imag;
  }
  EXPECT_LT(std::abs(sum / n), 5 / std::sqrt(n));
  EXPECT_LT(std::abs(sumSquares / n - 1), 5 * std::sqrt(2.0 / n));
  EXPECT_LT(std::abs(cross / (n / 2)), 5 / std::sqrt(n / 2.0));
}

TEST(OceanFftReference, SameSeedSameSeaOtherSeedOtherSea) {
  SpectrumSettings s;
  CascadeSettings c;
  c.resolution = 64;
  c.tileLengths = {400, 40};
  OceanCascade a = initialCascade(s, c, 0), b = initialCascade(s, c, 0);
  EXPECT_EQ(a.h0, b.h0);
  c.seed = 1;
  EXPECT_NE(initialCascade(s, c, 0).h0, a.h0);
  // Each cascade draws its own numbers: a second cascade is no copy of the first's bins.
  OceanCascade second = initialCascade(s, c, 1);
  EXPECT_NE(second.h0, initialCascade(s, c, 0).h0);
  // The Nyquist row and column (index N/2) have no mirror of their own: they stay empty,
  // as does the mean; the bins next to them do not.
  for (int m = 0; m < 64; ++m) {
    EXPECT_EQ(second.h0[static_cast<size_t>(32) * 64 + m], 0.0) << m;
    EXPECT_EQ(second.h0[static_cast<size_t>(m) * 64 + 32], 0.0) << m;
  }
  EXPECT_EQ(a.h0[0], 0.0);
  EXPECT_NE(second.h0[static_cast<size_t>(31) * 64 + 31], 0.0);
}

// The resolution is a quality knob: a lower one keeps the same sea and drops only the
// finest cascade's shortest waves. Every wave of the 128^2 sea is the 256^2 sea's at the
// same wavenumber (same amplitude, bit for bit); the 256^2 sea's other waves are all in the
// last cascade, beyond the 128^2 grid.
TEST(OceanFftReference, ALowerResolutionKeepsTheSeaAndDropsOnlyTheShortestWaves) {
  SpectrumSettings s;
  CascadeSettings fine, coarse;
  fine.tileLengths = coarse.tileLengths = {120, 24, 5};
  fine.resolution = 256;
  coarse.resolution = 128;
  for (int c = 0; c < 3; ++c) {
    OceanCascade a = initialCascade(s, coarse, c), b = initialCascade(s, fine, c);
    const double dk = 2 * kPi / a.tileLength;
    int extra = 0;
    for (int iz = 0; iz < 256; ++iz)
      for (int ix = 0; ix < 256; ++ix) {
        int mx = signedIndex(ix, 256), mz = signedIndex(iz, 256);
        std::complex<double> big = b.h0[static_cast<size_t>(iz) * 256 + ix];
        bool inCoarse = mx > -64 && mx < 64 && mz > -64 && mz < 64;
        if (inCoarse) {
          size_t j = static_cast<size_t>((mz + 128) % 128) * 128 + static_cast<size_t>((mx + 128) % 128);
          ASSERT_EQ(big, a.h0[j]) << "cascade " << c << " bin (" << mx << ", " << mz << ")";
        } else if (big != 0.0) {
          ++extra;
          EXPECT_EQ(c, 2) << "a wave of cascade " << c << " at k = " << dk * std::hypot(mx, mz) << " rad/m";
        }
      }
    if (c == 2) {
      EXPECT_GT(extra, 0) << "the finest cascade's shortest waves";
    }
  }
}

TEST(OceanFftReference, SurfaceVarianceIsTheSpectrumsIntegral) {
  // Parseval: the mean square of the surface is the sum of |h~(k)|^2, whose expectation the
  // amplitudes' scale makes the spectrum's m0. m0 is integrated here from E(k) (quadrature,
  // no FFT). A JONSWAP sea (U10 = 10 m/s, 100 km fetch, omega_p = 1.01 rad/s, a 60 m peak
  // wavelength) on one 1000 m tile at 256^2.
  SpectrumSettings s;
  CascadeSettings c;
  c.resolution = 256;
  c.tileLengths = {1000};
  double dk = 2 * M_PI / 1000, kMax = 127 * dk;
  double m0 = integrateWavenumbers(s, 1e-4, 1e3);
  // What the grid cannot hold: below its first bin and past the largest circle it holds
  // whole (its corners hold some of that, so this over-estimates the loss).
  double lost = integrateWavenumbers(s, 1e-4, dk) + integrateWavenumbers(s, kMax, 1e3);
  // The spread of one sea's mean square: |h~(k)|^2 is exponential with mean
  // P(k) = (F(k) + F(-k)) dk^2 / 2 and the bins k and -k hold the same value, so the
  // variance of the sum over all bins is 2 sum P^2; its relative spread is about 3.8 %
  // here (some 700 independent waves), so 64 seas are averaged: 0.47 %.
  const int seas = 64;
  int n = c.resolution;
  OceanCascade first = initialCascade(s, c, 0);
  double sumP = 0, sumP2 = 0;
  for (int iz = 0; iz < n; ++iz)
    for (int ix = 0; ix < n; ++ix) {
      size_t i = static_cast<size_t>(iz) * n + ix, mirror = static_cast<size_t>((n - iz) % n) * n + (n - ix) % n;
      double p = 0.5 * (first.binVariance[i] + first.binVariance[mirror]);
      sumP += p;
      sumP2 += p * p;
    }
  double spread = std::sqrt(2 * sumP2) / sumP / std::sqrt(seas);
  // The 3 % the issue asks for must hold the grid's loss and three standard errors.
  ASSERT_LT(lost / m0 + 3 * spread, 0.03) << lost / m0 << " " << spread;
  double mean = 0;
  for (int seed = 0; seed < seas; ++seed) {
    c.seed = seed;
    mean += meanSquare(oceanHeight(initialCascade(s, c, 0), 0.0)) / seas;
  }
  std::printf("m0 %.6f m^2, the surface's mean square over %d seas %.6f (%+.2f %%), loss <= %.2f %%, 1 sigma %.2f %%\n",
              m0, seas, mean, 100 * (mean / m0 - 1), 100 * lost / m0, 100 * spread);
  EXPECT_NEAR(mean, m0, 0.03 * m0);
  // The discretised spectrum alone (no random numbers) is within the grid's loss of m0.
  EXPECT_NEAR(sumP, m0, lost + 0.005 * m0);
}

TEST(OceanFftReference, PiersonMoskowitzSignificantHeightOverThreeCascades) {
  // A fully developed sea of U10 = 10 m/s (U19.5 = 10.26 m/s): Hs = 4 sqrt(m0) = 0.209 U19.5^2 / g
  // = 2.243 m, from the discretised spectrum summed over three cascades (each bin counted by
  // one cascade only: a band counted twice would double m0) and from the surfaces.
  SpectrumSettings s;
  s.model = SpectrumModel::PiersonMoskowitz;
  CascadeSettings c;
  c.tileLengths = {1000, 100, 10};
  double u = 1.026 * 10, expected = 0.209 * u * u / g;
  double m0 = 0.0081 * std::pow(u, 4) / (4 * 0.74 * g * g);  // the closed form
  EXPECT_NEAR(4 * std::sqrt(m0), expected, 0.05 * expected);
  double discretised = 0;
  for (int i = 0; i < 3; ++i)
    for (double v : initialCascade(s, c, i).binVariance) discretised += v;
  EXPECT_NEAR(4 * std::sqrt(discretised), expected, 0.05 * expected);
  // The surfaces: the cascades are independent, so their mean squares add. 8 seas; the
  // coarsest tile's spread dominates (~5 % in m0, ~2.5 % in Hs for one sea).
  double surface = 0;
  const int seas = 8;
  for (int seed = 0; seed < seas; ++seed) {
    c.seed = seed;
    for (int i = 0; i < 3; ++i) surface += meanSquare(oceanHeight(initialCascade(s, c, i), 3.0)) / seas;
  }
  std::printf("Hs: closed form %.4f m, discretised %.4f m, surfaces %.4f m, 0.209 U19.5^2/g %.4f m\n",
              4 * std::sqrt(m0), 4 * std::sqrt(discretised), 4 * std::sqrt(surface), expected);
  EXPECT_NEAR(4 * std::sqrt(surface), expected, 0.05 * expected);
}

// One bin (mx, mz) of a 64^2 cascade with amplitude a: h = 2|a| cos(k.x - omega t + arg a).
OceanCascade singleBin(double tileLength, double depth, int mx, int mz, std::complex<double> a) {
  OceanCascade c = emptyCascade(64, tileLength, depth);
  c.h0[static_cast<size_t>((mz + 64) % 64) * 64 + (mx + 64) % 64] = a;
  return c;
}

TEST(OceanFftReference, OneBinOscillatesWithTheDispersionPeriod) {
  // The period measured from the surface: upward zero crossings of h at one grid point,
  // each found by bisection on t, over 10 periods. The bins' frequencies are the nearest
  // multiples of 2 pi / 2^16 s (within pi / (2^16 s omega) relative) and time advances in
  // steps of 2^-16 s (a crossing found within one step: 1.5e-6 s over 10 periods, under
  // 1e-6 of these periods). The issue asks for 0.1 %.
  constexpr double kLoop = 65536;
  for (double depth : {5.0, 1.0 / 0.0}) {
    OceanCascade c = singleBin(100, depth, 3, -2, {0.25, 0.1});
    double k = 2 * M_PI / 100 * std::sqrt(13.0);
    double omega = std::sqrt(g * k * (std::isinf(depth) ? 1.0 : std::tanh(k * depth)));
    double period = 2 * M_PI / omega;
    auto height = [&](double t) { return oceanHeight(c, t)[5 * 64 + 7]; };
    std::vector<double> crossings;
    double step = period / 24, previous = height(0);
    for (double t = step; crossings.size() < 11; t += step) {
      double now = height(t);
      if (previous < 0 && now >= 0) {
        double lo = t - step, hi = t;
        for (int i = 0; i < 30; ++i) {
          double mid = 0.5 * (lo + hi);
          (height(mid) < 0 ? lo : hi) = mid;
        }
        crossings.push_back(0.5 * (lo + hi));
      }
      previous = now;
    }
    double measured = (crossings.back() - crossings.front()) / 10;
    EXPECT_NEAR(measured, period, (M_PI / (kLoop * omega) + 1e-6) * period) << depth;
    EXPECT_NEAR(measured, period, 1e-3 * period) << depth;
  }
}

TEST(OceanFftReference, OneWavesDisplacementSlopesAndJacobianAreItsClosedForm) {
  // h = A cos(theta), theta = k.x - omega t + phi. Then D = -(k/|k|) A sin(theta), the
  // slope is -k A sin(theta), and for one wave J = 1 - lambda A |k| cos(theta) exactly
  // (the lambda^2 terms cancel). FFTW's rounding is about log2(N) eps times the sum of
  // the coefficients' moduli (2 |a| |k|^p <= 1 here): 1e-13 holds it with room.
  const double amplitude = 0.5, phi = 0.3, lambda = 0.9, time = 2.75, depth = 12;
  OceanCascade c = singleBin(100, depth, 3, -2, std::polar(amplitude / 2, phi));
  OceanFields f = oceanFields(c, time, lambda);
  double dk = 2 * M_PI / 100, kx = 3 * dk, kz = -2 * dk, k = std::hypot(kx, kz);
  // The bin's frequency is the multiple of 2 pi / 2^16 s nearest to the dispersion's, and
  // 2.7 s is a whole number of 2^-16 s steps: the phase is exactly omega t.
  double omega = std::nearbyint(std::sqrt(g * k * std::tanh(k * depth)) * 65536 / (2 * M_PI)) * 2 * M_PI / 65536;
  double worstJ = 1;
  for (int jz = 0; jz < 64; ++jz)
    for (int jx = 0; jx < 64; ++jx) {
      size_t i = static_cast<size_t>(jz) * 64 + jx;
      double theta = kx * jx * 100 / 64 + kz * jz * 100 / 64 - omega * time + phi;
      EXPECT_NEAR(f.height[i], amplitude * std::cos(theta), 1e-13);
      EXPECT_NEAR(f.displacementX[i], -kx / k * amplitude * std::sin(theta), 1e-13);
      EXPECT_NEAR(f.displacementZ[i], -kz / k * amplitude * std::sin(theta), 1e-13);
      EXPECT_NEAR(f.slopeX[i], -kx * amplitude * std::sin(theta), 1e-13);
      EXPECT_NEAR(f.slopeZ[i], -kz * amplitude * std::sin(theta), 1e-13);
      EXPECT_NEAR(f.jacobian[i], 1 - lambda * amplitude * k * std::cos(theta), 1e-13);
      worstJ = std::min(worstJ, f.jacobian[i]);
    }
  // A positive lambda sharpens the crests: the surface is compressed (J < 1) where h is high.
  EXPECT_LT(worstJ, 1 - 0.9 * lambda * amplitude * k);
}

TEST(OceanFftReference, AMillionSecondsIsTheTimeModuloThePeriod) {
  // Phases are integers modulo 2^32 (the fraction of the 2^16 s loop times the bin's
  // frequency index), so t = 1e6 s is exactly t minus whole loops, and, within the time
  // step of 2^-16 s (|dh| <= A omega 2^-16), t modulo the bin's own period.
  OceanCascade c = singleBin(100, 1.0 / 0.0, 3, -2, {0.25, 0.1});
  double omega = angularFrequencyOf(c.frequency[static_cast<size_t>(62) * 64 + 3]);
  double period = 2 * M_PI / omega, t = 1e6;
  EXPECT_NEAR(omega, std::sqrt(g * 2 * M_PI / 100 * std::sqrt(13.0)), M_PI / 65536);
  OceanFields late = oceanFields(c, t, 1.0), loopsEarlier = oceanFields(c, t - 15 * 65536.0, 1.0);
  EXPECT_EQ(late.height, loopsEarlier.height);
  EXPECT_EQ(late.jacobian, loopsEarlier.jacobian);
  EXPECT_EQ(oceanHeight(c, t), late.height);  // the height alone is the same transform
  OceanFields early = oceanFields(c, t - period * std::floor(t / period), 1.0);
  double amplitude = 2 * std::abs(c.h0[static_cast<size_t>(62) * 64 + 3]);
  double bound = amplitude * omega * std::ldexp(1.0, -16);
  for (size_t i = 0; i < late.height.size(); ++i) {
    ASSERT_NEAR(late.height[i], early.height[i], bound) << i;
    ASSERT_NEAR(late.jacobian[i], early.jacobian[i], bound * 2 * M_PI / 100 * std::sqrt(13.0)) << i;
  }
  // A whole sea at 1e6 s: every field finite, and the sea still there.
  SpectrumSettings s;
  CascadeSettings cs;
  cs.resolution = 64;
  cs.tileLengths = {500, 50};
  for (int i = 0; i < 2; ++i) {
    OceanFields f = oceanFields(initialCascade(s, cs, i), t, 1.0);
    for (const auto* field : {&f.height, &f.displacementX, &f.displacementZ, &f.slopeX, &f.slopeZ, &f.jacobian})
      for (double v : *field) ASSERT_TRUE(std::isfinite(v));
    EXPECT_GT(meanSquare(f.height), 0.0);
  }
}

}  // namespace
}  // namespace wg::ocean
