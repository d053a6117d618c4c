#pragma once
// What the spectral ocean's foam tests share (ocean_gpu_foam_test.cpp on GL,
// vk_ocean_test.cpp on Vulkan): a stormy cascade, the double reference's foam at a time,
// and the bound of the float32 foam against it.
//
// The bound: the float32 Jacobian of a step differs from the double one by at most
// dJ <= |1 + l b| l db + |1 + l a| l da + 2 l^2 |c| dc + l^2 da db + l^2 dc^2 at each texel,
// where a, b, c are dDx/dx, dDz/dz, dDx/dz and da, db, dc the transform's error bound for
// the complex transform that holds them (a 2-norm over the grid, so a bound on every texel:
// tests/runtime/ocean_gpu_cascade_test.cpp derives it), plus the J product's own roundings
// (4u |J| and more). Each step adds gain dJ, the rounding of the constants (keep and gain
// and the threshold to float: u each, times the foam and the growth) and the step's own
// roundings (3u); the recurrence is a contraction by keep, so the foam's error is at most
// the per-step error / (1 - keep). The frame's blend adds 3u.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/ocean_fft_reference.h"
#include "core/ocean_foam.h"
#include "ocean_transform_bound.h"

namespace wg::rt::ocean_test {

inline ocean::OceanCascade storm(int resolution) {
  ocean::SpectrumSettings s;
  s.windSpeed = 25;
  s.fetch = 500e3;
  ocean::CascadeSettings c;
  c.resolution = resolution;
  c.tileLengths = {150};
  c.choppiness = 2.5;
  return ocean::initialCascade(s, c, 0);
}

// The bound on every texel of the foam at time t (header comment), over the steps a replay
// of t runs.
inline double foamBound(const ocean::OceanCascade& cascade, double lambda, const ocean::FoamSettings& f, double t) {
  const std::int64_t n = ocean::stepIndex(f, t);
  const double u = kUnitRoundoff;
  const double e = transformBound(cascade.resolution);
  double worstStep = 0;
  for (std::int64_t m = n - ocean::historySteps(f) + 1; m <= n + 1; ++m) {
    ocean::OceanFields fields = ocean::oceanFields(cascade, static_cast<double>(m) * f.step, lambda);
    // The second texture's two complex transforms: (dh/dz + i dDx/dx), (dDz/dz + i dDx/dz).
    const double first = e * std::hypot(norm(fields.slopeZ), norm(fields.dDxdx));
    const double second = e * std::hypot(norm(fields.dDzdz), norm(fields.dDxdz));
    double dJ = 0;
    for (size_t i = 0; i < fields.jacobian.size(); ++i) {
      const double a = fields.dDxdx[i], b = fields.dDzdz[i], c = fields.dDxdz[i];
      const double da = first, db = second, dc = second;
      double here = std::abs(1 + lambda * b) * lambda * da + std::abs(1 + lambda * a) * lambda * db +
                    2 * lambda * lambda * std::abs(c) * dc + lambda * lambda * (da * db + dc * dc);
      // The products by lambda, the sums and products of J: a handful of roundings of
      // terms of size (1 + |l a|)(1 + |l b|) + (l c)^2.
      here += 6 * u * ((1 + std::abs(lambda * a)) * (1 + std::abs(lambda * b)) + lambda * lambda * c * c);
      dJ = std::max(dJ, here);
    }
    const double gain = ocean::foamGain(f);
    double step = gain * dJ + 3 * u + u * gain * std::abs(f.threshold) + u * gain * 2 /* the threshold gap's float */ +
                  u /* keep rounded */ + u * gain /* gain rounded, times a deficit below 1 + |threshold| */;
    worstStep = std::max(worstStep, step);
  }
  return worstStep / (1 - ocean::foamKeep(f)) + 3 * u;
}

// The reference's foam at t at every texel: f_n + (f_(n+1) - f_n) fraction.
inline std::vector<double> referenceFoam(const ocean::OceanCascade& cascade, double lambda, const ocean::FoamSettings& f,
                                  double t) {
  ocean::FoamMaps maps = ocean::replayFoam(cascade, lambda, f, ocean::stepIndex(f, t));
  const double fraction = ocean::foamFraction(f, t);
  std::vector<double> out(maps.current.size());
  for (size_t i = 0; i < out.size(); ++i) out[i] = maps.current[i] + (maps.next[i] - maps.current[i]) * fraction;
  return out;
}

inline double worstDifference(const std::vector<float>& gpu, const std::vector<double>& reference) {
  double worst = 0;
  for (size_t i = 0; i < gpu.size(); ++i) worst = std::max(worst, std::abs(gpu[i] - reference[i]));
  return worst;
}

}  // namespace wg::rt::ocean_test
