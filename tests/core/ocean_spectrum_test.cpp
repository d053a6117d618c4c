// The spectral ocean's spectra, spreading and dispersion (core/ocean_spectrum.h) against
// values worked out here: the dispersion relation written out, Kitaigorodskii's factor from
// its definition (the k^-3 range's frequency spectrum at depth over that in deep water,
// with k(omega) solved here by bisection), Pierson-Moskowitz's closed-form variance, the
// JONSWAP peak's height and place, and every spreading function integrating to 1.
#include <cmath>
#include <functional>

#include <gtest/gtest.h>

#include "core/ocean_spectrum.h"
#include "ocean_test_support.h"

namespace wg::ocean {
namespace {

using namespace test_support;



// The integral over [-1, 1] by the tanh-sinh rule, which keeps its accuracy when the
// integrand's derivatives blow up at the ends (cos-2s with s < 1 at theta = +-pi).
double tanhSinh(const std::function<double(double)>& f) {
  double h = 1.0 / 64, sum = 0;
  for (double t = -4; t <= 4 + 1e-12; t += h) {
    double u = 0.5 * M_PI * std::sinh(t), x = std::tanh(u);
    sum += f(x) * 0.5 * M_PI * std::cosh(t) / (std::cosh(u) * std::cosh(u));
  }
  return sum * h;
}

// The integral over (0, inf) of a spectrum peaked near x0, on a logarithmic grid from x0/50
// to 2000 x0 (an omega^-5 tail past that holds under 1e-13 of the total).
double integratePeaked(const std::function<double(double)>& f, double x0) {
  return simpson([&](double u) { return f(std::exp(u)) * std::exp(u); }, std::log(x0 / 50), std::log(x0 * 2000), 40000);
}

// omega(k) as the relation is written, and k(omega) by bisection on it.
double dispersion(double k, double d) { return std::sqrt(g * k * std::tanh(k * d)); }
double wavenumberOf(double omega, double d) {
  double lo = 0, hi = 1;
  while (dispersion(hi, d) < omega) hi *= 2;
  for (int i = 0; i < 200; ++i) {
    double mid = 0.5 * (lo + hi);
    (dispersion(mid, d) < omega ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(OceanSpectrum, DispersionInDeepFiniteAndVeryShallowWater) {
  for (double k : {1e-3, 0.05, 0.7, 12.0}) {
    EXPECT_NEAR(angularFrequency(k, kInf), std::sqrt(g * k), 1e-14 * std::sqrt(g * k)) << k;
    for (double d : {0.5, 4.0, 30.0})
      EXPECT_NEAR(angularFrequency(k, d), dispersion(k, d), 1e-13 * dispersion(k, d)) << k << " " << d;
  }
  // kd = 1e-9: omega = k sqrt(g d) (1 - (kd)^2 / 6): the library's series, not 0.
  EXPECT_NEAR(angularFrequency(1e-3, 1e-6), 1e-3 * std::sqrt(g * 1e-6), 1e-15 * 1e-3 * std::sqrt(g * 1e-6));
  EXPECT_EQ(angularFrequency(0.0, 10.0), 0.0);
  // The group velocity: a central difference of the relation written out (its error is
  // h^2 omega''' / 6, under 1e-8 relative at h = 1e-5 k).
  for (double d : {2.0, 30.0, kInf})
    for (double k : {0.01, 0.3, 3.0}) {
      double h = 1e-5 * k;
      double numeric = (dispersion(k + h, d) - dispersion(k - h, d)) / (2 * h);
      EXPECT_NEAR(groupVelocity(k, d), numeric, 1e-8 * numeric) << k << " " << d;
    }
  EXPECT_NEAR(groupVelocity(1e-9, 3.0), std::sqrt(g * 3.0), 1e-12);  // shallow waves do not disperse
}

TEST(OceanSpectrum, TmaFactorIsKitaigorodskiisRatio) {
  // Phi(omega, d) = [k^-3 dk/domega] / [k_inf^-3 dk_inf/domega], k_inf = omega^2 / g, from
  // the definition with k(omega) by bisection and dk/domega by central difference.
  for (double d : {1.0, 5.0, 20.0})
    for (double omega : {0.3, 0.8, 1.5, 3.0}) {
      double k = wavenumberOf(omega, d), h = 1e-5 * omega;
      double dkdw = (wavenumberOf(omega + h, d) - wavenumberOf(omega - h, d)) / (2 * h);
      double kInfinite = omega * omega / g, dkInfinite = 2 * omega / g;
      double phi = (dkdw / (k * k * k)) / (dkInfinite / (kInfinite * kInfinite * kInfinite));
      EXPECT_NEAR(tmaDepthFactor(k, d), phi, 1e-7 * phi) << d << " " << omega;
    }
  // Kitaigorodskii's shallow limit omega_h^2 / 2 (omega_h = omega sqrt(d / g)), error O(omega_h^4).
  double d = 1.0, k = 1e-3, omegaH = dispersion(k, d) * std::sqrt(d / g);
  EXPECT_NEAR(tmaDepthFactor(k, d), omegaH * omegaH / 2, 1e-5 * omegaH * omegaH);
  EXPECT_EQ(tmaDepthFactor(0.1, kInf), 1.0);
  EXPECT_EQ(tmaDepthFactor(0.1, 1e4), 1.0);
}

TEST(OceanSpectrum, PiersonMoskowitzVarianceIsItsClosedForm) {
  // m0 = alpha U^4 / (4 beta g^2) with U = U19.5 = 1.026 U10 (alpha 0.0081, beta 0.74), and
  // Hs = 4 sqrt(m0) = 2 sqrt(alpha / beta) U^2 / g = 0.2092 U^2 / g: Pierson and Moskowitz's 0.209.
  for (double u10 : {5.0, 10.0, 20.0}) {
    double u = 1.026 * u10;
    double closed = 0.0081 * std::pow(u, 4) / (4 * 0.74 * g * g);
    double m0 = integratePeaked([&](double w) { return piersonMoskowitzSpectrum(w, u10); }, g / u);
    EXPECT_NEAR(m0, closed, 1e-9 * closed) << u10;
    double hs = 4 * std::sqrt(m0);
    EXPECT_NEAR(hs, 0.209 * u * u / g, 0.05 * 0.209 * u * u / g) << u10;
    EXPECT_NEAR(hs, 0.209 * u * u / g, 0.002 * 0.209 * u * u / g) << u10;  // in fact within 0.2 %
    // The peak: dS/domega = 0 at omega = (4 beta / 5)^(1/4) g / U = 0.877 g / U19.5.
    EXPECT_NEAR(piersonMoskowitzPeak(u10), std::pow(0.8 * 0.74, 0.25) * g / u, 1e-14);
  }
}

TEST(OceanSpectrum, JonswapPeakFetchLawsAndItsPiersonMoskowitzLimit) {
  // Fetch laws at U10 = 10 m/s, F = 100 km, as Hasselmann et al. write them.
  JonswapParameters p = jonswapParameters(10, 100e3);
  EXPECT_NEAR(p.alpha, 0.076 * std::pow(100.0 / (100e3 * g), 0.22), 1e-15);
  EXPECT_NEAR(p.omegaPeak, 22 * std::cbrt(g * g / (10 * 100e3)), 1e-13);
  // The spectrum peaks at omega_p, where the enhancement is exactly gamma.
  double best = 0, bestOmega = 0;
  for (double w = 0.5; w < 2.0; w += 1e-5) {
    double s = jonswapSpectrum(w, p, 3.3);
    if (s > best) best = s, bestOmega = w;
  }
  EXPECT_NEAR(bestOmega, p.omegaPeak, 1e-5);
  double base = p.alpha * g * g * std::pow(p.omegaPeak, -5) * std::exp(-1.25);
  EXPECT_NEAR(jonswapSpectrum(p.omegaPeak, p, 3.3) / base, 3.3, 1e-12);
  // One width below the peak (sigma_a = 0.07) and one above (sigma_b = 0.09) the
  // enhancement is gamma^exp(-1/2).
  for (double x : {1 - 0.07, 1 + 0.09}) {
    double w = x * p.omegaPeak;
    double plain = p.alpha * g * g * std::pow(w, -5) * std::exp(-1.25 / std::pow(x, 4));
    EXPECT_NEAR(jonswapSpectrum(w, p, 3.3) / plain, std::pow(3.3, std::exp(-0.5)), 1e-12) << x;
  }
  // With gamma = 1, alpha = 0.0081 and Pierson-Moskowitz's peak it is Pierson-Moskowitz.
  JonswapParameters pm{0.0081, piersonMoskowitzPeak(10)};
  for (double w : {0.4, 0.85, 1.3, 4.0})
    EXPECT_NEAR(jonswapSpectrum(w, pm, 1.0), piersonMoskowitzSpectrum(w, 10), 1e-12 * piersonMoskowitzSpectrum(w, 10));
  // Past the fully developed fetch nothing grows, and there omega_p is Pierson-Moskowitz's.
  double chiMax = fullyDevelopedFetch();
  JonswapParameters capped = jonswapParameters(10, chiMax * 100 / g), beyond = jonswapParameters(10, 1e12);
  EXPECT_NEAR(capped.omegaPeak, piersonMoskowitzPeak(10), 1e-12);
  EXPECT_EQ(beyond.omegaPeak, capped.omegaPeak);
  EXPECT_EQ(beyond.alpha, capped.alpha);
  EXPECT_NEAR(chiMax, 1.70e4, 0.01e4);
}

TEST(OceanSpectrum, TmaInDeepWaterIsJonswap) {
  SpectrumSettings jonswap, tma;
  tma.model = SpectrumModel::Tma;
  tma.depth = 1e4;  // kd >= 60 for every wavenumber below
  for (double k = 0.006; k < 50; k *= 1.3) {
    EXPECT_EQ(windSeaFrequencySpectrum(tma, k), windSeaFrequencySpectrum(jonswap, k)) << k;
    EXPECT_EQ(directionalSpectrum(tma, k, 0.3 * k), directionalSpectrum(jonswap, k, 0.3 * k)) << k;
  }
  // In 5 m of water the long waves lose energy, by the factor at each k.
  tma.depth = jonswap.depth = 5;
  double k = 0.1;
  EXPECT_NEAR(windSeaFrequencySpectrum(tma, k), windSeaFrequencySpectrum(jonswap, k) * tmaDepthFactor(k, 5), 1e-15);
  EXPECT_LT(tmaDepthFactor(k, 5), 0.5);
}

TEST(OceanSpectrum, SpreadingFunctionsIntegrateToOne) {
  // Each half circle on its own, so that the rule's nodes crowd both at the poles (+-pi)
  // and at the peak of a narrow spread (0).
  auto overCircle = [](const std::function<double(double)>& d) {
    return 0.5 * M_PI * (tanhSinh([&](double x) { return d(0.5 * M_PI * (x - 1)); }) +
                         tanhSinh([&](double x) { return d(0.5 * M_PI * (x + 1)); }));
  };
  for (double s : {0.0, 0.5, 1.0, 7.3, 40.0, 900.0})
    EXPECT_NEAR(overCircle([&](double t) { return cos2sNormalisation(s) * std::pow(std::cos(t / 2), 2 * s); }), 1.0,
                1e-9)
        << s;
  double wp = 0.9, u = 12;
  for (Spreading m : {Spreading::Cos2, Spreading::Mitsuyasu, Spreading::Hasselmann})
    for (double x : {0.3, 1.0, 1.04, 1.06, 2.5, 8.0}) {
      EXPECT_NEAR(overCircle([&](double t) { return directionalSpreading(m, t, x * wp, wp, u); }), 1.0, 1e-9)
          << static_cast<int>(m) << " " << x;
      EXPECT_GT(directionalSpreading(m, 0.0, x * wp, wp, u), directionalSpreading(m, 1.2, x * wp, wp, u));
    }
  // Worked values of the exponents (Hasselmann 1980 at the peak and at 2 omega_p for
  // U / c_p = 1.17; Mitsuyasu's s_max = 11.5 (omega_p U / g)^-2.5 at the peak).
  EXPECT_NEAR(hasselmannExponent(1.0, 1.0, 1.17 * g), 6.97, 1e-12);
  EXPECT_NEAR(hasselmannExponent(0.5, 1.0, 1.17 * g), 6.97 * std::pow(0.5, 4.06), 1e-12);
  EXPECT_NEAR(hasselmannExponent(2.0, 1.0, 1.17 * g), 9.77 * std::pow(2.0, -2.33), 1e-12);
  EXPECT_NEAR(mitsuyasuExponent(0.9, 0.9, 12), 11.5 * std::pow(0.9 * 12 / g, -2.5), 1e-12);
  EXPECT_NEAR(mitsuyasuExponent(1.8, 0.9, 12), 11.5 * std::pow(0.9 * 12 / g, -2.5) * std::pow(2.0, -2.5), 1e-12);
  // Cos-2s waves travel with the wind: none against it. Cos^2 (Phillips) sends as many back.
  EXPECT_LT(directionalSpreading(Spreading::Hasselmann, M_PI, 1.0, 1.0, 10), 1e-200);
  EXPECT_NEAR(directionalSpreading(Spreading::Cos2, M_PI, 1.0, 1.0, 10), 1 / M_PI, 1e-15);
}

TEST(OceanSpectrum, WavenumberSpectraHoldTheFrequencySpectrumsVariance) {
  // integral of E(k) dk = integral of S(omega) domega (E = S domega/dk), in deep water and
  // at 8 m; and the directional F, integrated over the circle of radius k, gives E(k) back.
  for (double depth : {kInf, 8.0}) {
    SpectrumSettings s;
    s.model = SpectrumModel::Jonswap;
    s.depth = depth;
    s.swell.height = 1.5;
    s.swell.period = 12;
    s.swell.direction = 0.7;
    double wp = jonswapParameters(s.windSpeed, s.fetch).omegaPeak;
    double fromOmega = integratePeaked([&](double w) { return jonswapSpectrum(w, jonswapParameters(10, 100e3), 3.3); },
                                       wp) +
                       1.5 * 1.5 / 16;  // the swell's Hs^2 / 16
    double fromK = integratePeaked([&](double k) { return omnidirectionalSpectrum(s, k); }, wavenumberOf(wp, depth));
    EXPECT_NEAR(fromK, fromOmega, 1e-6 * fromOmega) << depth;
    for (double k : {0.02, 0.1, 0.5}) {
      double around = simpson([&](double t) { return directionalSpectrum(s, k * std::cos(t), k * std::sin(t)) * k; },
                              -M_PI, M_PI, 20000);
      EXPECT_NEAR(around, omnidirectionalSpectrum(s, k), 1e-8 * omnidirectionalSpectrum(s, k)) << k;
    }
  }
  // The swell alone holds Hs^2 / 16.
  EXPECT_NEAR(integratePeaked([](double w) { return swellSpectrum(w, 2.0, 0.5); }, 0.5), 0.25, 1e-9);
}

TEST(OceanSpectrum, PhillipsIsTessendorfsFormula) {
  // F(k) = A exp(-1 / (k Lw)^2) / k^4 |k.w|^2 (Lw = U^2 / g), deep water, cos^2 spreading.
  SpectrumSettings s;
  s.model = SpectrumModel::Phillips;
  s.spreading = Spreading::Cos2;
  s.windSpeed = 15;
  s.phillipsAmplitude = 2e-3;
  s.windDirection = 0.4;
  double lw = 15.0 * 15.0 / g;
  for (double kx : {-0.3, 0.01, 0.2})
    for (double kz : {-0.05, 0.08}) {
      double k = std::hypot(kx, kz), dot = (kx * std::cos(0.4) + kz * std::sin(0.4)) / k;
      double expected = 2e-3 * std::exp(-1 / (k * lw * k * lw)) / std::pow(k, 4) * dot * dot;
      EXPECT_NEAR(directionalSpectrum(s, kx, kz), expected, 1e-12 * expected) << kx << " " << kz;
    }
}

}  // namespace
}  // namespace wg::ocean
