#include "nodes/noise_reference.h"

#include <algorithm>
#include <cmath>

#include "nodes/eval_math.h"

namespace wg::nodes::noise {

std::uint32_t cellOf(double x) {
  if (std::isnan(x)) return 0u;
  double c = glsl::clamp(std::floor(x), -2147483648.0, 2147483520.0);
  return static_cast<std::uint32_t>(static_cast<std::int32_t>(c));
}

U3 pcg3d(U3 v) {
  for (auto& c : v) c = c * 1664525u + 1013904223u;
  v[0] += v[1] * v[2];
  v[1] += v[2] * v[0];
  v[2] += v[0] * v[1];
  for (auto& c : v) c ^= c >> 16u;
  v[0] += v[1] * v[2];
  v[1] += v[2] * v[0];
  v[2] += v[0] * v[1];
  return v;
}

double unitOf(std::uint32_t h) { return static_cast<double>(h >> 8u) * 5.9604644775390625e-8; }

namespace {
std::array<double, 3> units(const U3& h) { return {unitOf(h[0]), unitOf(h[1]), unitOf(h[2])}; }
double lattice(std::uint32_t x, std::uint32_t y, std::uint32_t z) { return unitOf(pcg3d({x, y, z})[0]); }
double hermite(double f) { return f * f * (3.0 - 2.0 * f); }
}  // namespace

std::array<double, 3> hash2(double x, double y) { return units(pcg3d({cellOf(x), cellOf(y), 0u})); }
std::array<double, 3> hash3(double x, double y, double z) { return units(pcg3d({cellOf(x), cellOf(y), cellOf(z)})); }

double valueNoise2(double x, double y) {
  double fx = x - std::floor(x), fy = y - std::floor(y);
  std::uint32_t cx = cellOf(x), cy = cellOf(y);
  double ux = hermite(fx), uy = hermite(fy);
  double a = lattice(cx, cy, 0u), b = lattice(cx + 1u, cy, 0u);
  double d = lattice(cx, cy + 1u, 0u), e = lattice(cx + 1u, cy + 1u, 0u);
  return glsl::mix(glsl::mix(a, b, ux), glsl::mix(d, e, ux), uy);
}

double valueNoise3(double x, double y, double z) {
  double fx = x - std::floor(x), fy = y - std::floor(y), fz = z - std::floor(z);
  std::uint32_t cx = cellOf(x), cy = cellOf(y), cz = cellOf(z);
  double ux = hermite(fx), uy = hermite(fy), uz = hermite(fz);
  double v000 = lattice(cx, cy, cz), v100 = lattice(cx + 1u, cy, cz);
  double v010 = lattice(cx, cy + 1u, cz), v110 = lattice(cx + 1u, cy + 1u, cz);
  double v001 = lattice(cx, cy, cz + 1u), v101 = lattice(cx + 1u, cy, cz + 1u);
  double v011 = lattice(cx, cy + 1u, cz + 1u), v111 = lattice(cx + 1u, cy + 1u, cz + 1u);
  double z0 = glsl::mix(glsl::mix(v000, v100, ux), glsl::mix(v010, v110, ux), uy);
  double z1 = glsl::mix(glsl::mix(v001, v101, ux), glsl::mix(v011, v111, ux), uy);
  return glsl::mix(z0, z1, uz);
}

double valueNoiseTiled2(double x, double y, std::uint32_t mask) {
  double fx = x - std::floor(x), fy = y - std::floor(y);
  std::uint32_t cx = cellOf(x), cy = cellOf(y);
  std::uint32_t c1x = (cx + 1u) & mask, c1y = (cy + 1u) & mask;
  cx &= mask;
  cy &= mask;
  double ux = hermite(fx), uy = hermite(fy);
  double a = lattice(cx, cy, 0u), b = lattice(c1x, cy, 0u);
  double d = lattice(cx, c1y, 0u), e = lattice(c1x, c1y, 0u);
  return glsl::mix(glsl::mix(a, b, ux), glsl::mix(d, e, ux), uy);
}

double fbm2(double x, double y, int octaves, double lacunarity, double gain) {
  double lac = glsl::clamp(lacunarity, 0.0, 8.0), g = glsl::clamp(gain, 0.0, 4.0);
  double sum = 0, norm = 0, amp = 1, qx = x, qy = y;
  for (int i = 0; i < 8 && i < octaves; ++i) {
    sum += amp * valueNoise2(qx + i * 17.31, qy + i * 9.73);
    norm += amp;
    amp *= g;
    qx *= lac;
    qy *= lac;
  }
  return sum / norm;
}

double fbm3(double x, double y, double z, int octaves, double lacunarity, double gain) {
  double lac = glsl::clamp(lacunarity, 0.0, 8.0), g = glsl::clamp(gain, 0.0, 4.0);
  double sum = 0, norm = 0, amp = 1, qx = x, qy = y, qz = z;
  for (int i = 0; i < 8 && i < octaves; ++i) {
    sum += amp * valueNoise3(qx + i * 17.31, qy + i * 9.73, qz + i * 5.47);
    norm += amp;
    amp *= g;
    qx *= lac;
    qy *= lac;
    qz *= lac;
  }
  return sum / norm;
}

VoronoiResult voronoi(double x, double y, double jitter, double phase, bool animated, bool full) {
  double cfx = std::floor(x), cfy = std::floor(y);
  double fx = x - cfx, fy = y - cfy;
  std::uint32_t cx = cellOf(x), cy = cellOf(y);
  int loX = full ? -1 : (fx < 0.5 ? -1 : 0);  // step(0.5, f) - 1
  int loY = full ? -1 : (fy < 0.5 ? -1 : 0);
  int n = full ? 3 : 2;
  double j = glsl::clamp(jitter, 0.0, 1.0);
  VoronoiResult r;
  r.f1 = r.f2 = 1e30;
  int bestX = 0, bestY = 0;
  for (int jy = 0; jy < n; ++jy)
    for (int ix = 0; ix < n; ++ix) {
      int ox = loX + ix, oy = loY + jy;
      U3 h = pcg3d({cx + static_cast<std::uint32_t>(ox), cy + static_cast<std::uint32_t>(oy), 0u});
      double hx = unitOf(h[0]), hy = unitOf(h[1]);
      double wx = animated ? 0.5 * std::sin(phase + kTau * hx) : hx - 0.5;
      double wy = animated ? 0.5 * std::cos(phase + kTau * hy) : hy - 0.5;
      double qx = ox + (0.5 + j * wx) - fx, qy = oy + (0.5 + j * wy) - fy;
      double d = std::sqrt(qx * qx + qy * qy);
      if (d < r.f1) {
        r.f2 = r.f1;
        r.f1 = d;
        bestX = ox;
        bestY = oy;
      } else if (d < r.f2) {
        r.f2 = d;
      }
    }
  r.cellX = cfx + bestX;
  r.cellY = cfy + bestY;
  return r;
}

}  // namespace wg::nodes::noise
