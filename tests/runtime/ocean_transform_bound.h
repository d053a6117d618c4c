#pragma once
// What the spectral ocean's GPU tests share (ocean_gpu_cascade_test.cpp, ocean_gpu_foam_test.cpp):
// the float32 radix-2 FFT's relative error bound and a 2-norm. The bound (Higham, Accuracy
// and Stability of Numerical Algorithms, 2nd ed., thm. 24.2): a radix-2 FFT of length n in
// arithmetic of unit roundoff u, with twiddles accurate to mu, computes y with
// ||y^ - y||_2 <= (log2 n) eta / (1 - (log2 n) eta) ||y||_2, eta = mu + gamma_4 (sqrt 2 + mu),
// gamma_4 = 4u / (1 - 4u); the 2-D transform is the 1-D one along x then along z
// (log2 n = 2 log2 N); the twiddles are rounded once from double (mu = u); the evolution
// pass adds 16u (ocean_gpu_cascade_test.cpp counts them).
#include <cmath>
#include <vector>

namespace wg::rt::ocean_test {

inline constexpr double kUnitRoundoff = 5.9604644775390625e-8;  // 2^-24

inline double norm(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return std::sqrt(s);
}

inline double transformBound(int resolution) {
  const double u = kUnitRoundoff;
  double stages = 2 * std::log2(resolution);
  double gamma4 = 4 * u / (1 - 4 * u);
  double eta = u + gamma4 * (std::sqrt(2.0) + u);
  return stages * eta / (1 - stages * eta) + 16 * u;
}

}  // namespace wg::rt::ocean_test
