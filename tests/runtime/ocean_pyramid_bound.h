#pragma once
// What the filtered ocean's pyramid tests share (ocean_pyramid_test.cpp): a GPU pyramid
// (ocean_downsample's 2x2 box means, level by level) against the exact box means of its own
// level 0, within float32 rounding.
//
// The bound: level l is fl(((a + b) + (c + d)) / 4) of level l - 1's four texels. Whatever
// order a compiler sums them in, a 4-term float sum errs by at most gamma_3 times the sum of
// the terms' magnitudes (Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed.,
// eq. 4.4), and the product by 1/4 is exact. So the error e_l of a texel against the exact
// mean P_l of its block of level 0 obeys e_l <= (1 + gamma_3) box(e_(l-1)) + gamma_3 A_l,
// A_l the mean of |level 0| over the block, hence e_l <= l gamma_3 (1 + l gamma_3) A_l; plus
// 2^-126 per level for a driver that flushes subnormal results to zero.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "ocean_transform_bound.h"

namespace wg::rt::ocean_test {

struct PyramidCheck {
  double worst = 0;      // the largest error / bound (0 when every level is exact)
  std::string failure;   // the first texel over its bound, or empty
};

// `levels[l]` is level l read back ((n >> l)^2 RGBA texels, row-major).
inline PyramidCheck checkPyramid(const std::vector<std::vector<float>>& levels, int n) {
  const double u = kUnitRoundoff, gamma3 = 3 * u / (1 - 3 * u), flush = std::ldexp(1.0, -126);
  PyramidCheck out;
  // The exact means of level 0 and of its magnitudes, level by level.
  std::vector<double> exact(levels[0].begin(), levels[0].end()), magnitude(exact.size());
  for (size_t i = 0; i < exact.size(); ++i) magnitude[i] = std::abs(exact[i]);
  for (size_t l = 1; l < levels.size(); ++l) {
    const int above = n >> (l - 1), size = n >> l;
    std::vector<double> e(static_cast<size_t>(size) * size * 4), m(e.size());
    for (int z = 0; z < size; ++z)
      for (int x = 0; x < size; ++x)
        for (int c = 0; c < 4; ++c) {
          auto at = [&](const std::vector<double>& v, int dx, int dz) {
            return v[(static_cast<size_t>(2 * z + dz) * above + (2 * x + dx)) * 4 + c];
          };
          const size_t i = (static_cast<size_t>(z) * size + x) * 4 + c;
          e[i] = (at(exact, 0, 0) + at(exact, 1, 0) + at(exact, 0, 1) + at(exact, 1, 1)) / 4;
          m[i] = (at(magnitude, 0, 0) + at(magnitude, 1, 0) + at(magnitude, 0, 1) + at(magnitude, 1, 1)) / 4;
        }
    exact = std::move(e);
    magnitude = std::move(m);
    const double k = static_cast<double>(l);
    for (size_t i = 0; i < exact.size(); ++i) {
      const double error = std::abs(levels[l][i] - exact[i]);
      const double bound = k * gamma3 * (1 + k * gamma3) * magnitude[i] + k * flush;
      if (error > 0) out.worst = std::max(out.worst, error / bound);
      if (error > bound && out.failure.empty()) {
        char text[200];
        std::snprintf(text, sizeof text, "level %zu texel %zu channel %zu: %.9g, the box mean %.9g (error %.3g > bound %.3g)",
                      l, i / 4, i % 4, static_cast<double>(levels[l][i]), exact[i], error, bound);
        out.failure = text;
      }
    }
  }
  return out;
}

}  // namespace wg::rt::ocean_test
