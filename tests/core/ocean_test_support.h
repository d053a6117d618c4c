#pragma once
// What the spectral ocean's tests share: constants and Simpson's rule, written here once so
// the tests' own integrals do not depend on the code under test.
#include <functional>
#include <limits>

namespace wg::ocean::test_support {

inline constexpr double g = 9.81;
inline constexpr double kInf = std::numeric_limits<double>::infinity();

// Composite Simpson's rule on [a, b] with n (even) intervals.
inline double simpson(const std::function<double(double)>& f, double a, double b, int n) {
  double h = (b - a) / n, sum = f(a) + f(b);
  for (int i = 1; i < n; ++i) sum += f(a + i * h) * (i % 2 ? 4 : 2);
  return sum * h / 3;
}

}  // namespace wg::ocean::test_support
