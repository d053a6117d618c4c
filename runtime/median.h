#pragma once
// The median of a list of timings (0 for none): what every frame-time figure quotes, since
// a shared machine's slow frames would pull a mean.
#include <algorithm>
#include <vector>

namespace wg::rt {

inline double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace wg::rt
