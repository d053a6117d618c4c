// Counter-based Gaussian numbers (core/ocean_random.h).
#include "core/ocean_random.h"

#include <cmath>

namespace wg::ocean {
namespace {

void mix(std::array<std::uint32_t, 4>& v) {
  v[0] += v[1] * v[3];
  v[1] += v[2] * v[0];
  v[2] += v[0] * v[1];
  v[3] += v[1] * v[2];
}

}  // namespace

std::array<std::uint32_t, 4> pcg4d(std::array<std::uint32_t, 4> v) {
  for (auto& x : v) x = x * 1664525u + 1013904223u;
  mix(v);
  for (auto& x : v) x ^= x >> 16u;
  mix(v);
  return v;
}

GaussianPair binGaussians(std::uint32_t cascade, std::uint32_t ix, std::uint32_t iz, std::uint32_t seed) {
  auto h = pcg4d({ix, iz, cascade, seed});
  constexpr double kTwoTo32 = 4294967296.0;
  double u1 = (static_cast<double>(h[0]) + 1.0) / kTwoTo32;  // never 0: log stays finite
  double u2 = static_cast<double>(h[1]) / kTwoTo32;
  double r = std::sqrt(-2.0 * std::log(u1));
  double a = 2.0 * 3.14159265358979323846 * u2;
  return {r * std::cos(a), r * std::sin(a)};
}

}  // namespace wg::ocean
