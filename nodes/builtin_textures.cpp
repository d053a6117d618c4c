// The built-in procedural textures: tileable, deterministic (integer hashing only, no
// platform maths in the texel values' integer part), 256 x 256 RGBA8.
#include <cmath>
#include <map>
#include <mutex>
#include <string>

#include "core/interface_tables.h"
#include "nodes/texture_source.h"

namespace wg {
namespace {

constexpr int kSize = 256;

// PCG-style integer hash (Jarzynski and Olano, "Hash Functions for GPU Rendering", 2020).
std::uint32_t hash32(std::uint32_t v) {
  std::uint32_t state = v * 747796405u + 2891336453u;
  std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

double latticeValue(int x, int y, int period, std::uint32_t seed) {
  std::uint32_t ix = static_cast<std::uint32_t>(((x % period) + period) % period);
  std::uint32_t iy = static_cast<std::uint32_t>(((y % period) + period) % period);
  return hash32(ix + hash32(iy + hash32(seed))) / 4294967295.0;
}

// Value noise over a lattice of `period` cells across the texture: tiles seamlessly.
double valueNoise(double u, double v, int period, std::uint32_t seed) {
  double x = u * period, y = v * period;
  int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  double tx = x - x0, ty = y - y0;
  tx = tx * tx * (3 - 2 * tx);
  ty = ty * ty * (3 - 2 * ty);
  double a = latticeValue(x0, y0, period, seed), b = latticeValue(x0 + 1, y0, period, seed);
  double c = latticeValue(x0, y0 + 1, period, seed), d = latticeValue(x0 + 1, y0 + 1, period, seed);
  return (a + (b - a) * tx) + ((c + (d - c) * tx) - (a + (b - a) * tx)) * ty;
}

double fbm(double u, double v, std::uint32_t seed) {
  double sum = 0, amp = 0.5, norm = 0;
  for (int octave = 0, period = 4; octave < 5; ++octave, period *= 2, amp *= 0.5) {
    sum += amp * valueNoise(u, v, period, seed + static_cast<std::uint32_t>(octave) * 101u);
    norm += amp;
  }
  return sum / norm;
}

// Distance to the nearest of one jittered point per cell (F1), tileable.
double cellDistance(double u, double v, int period, std::uint32_t seed) {
  double x = u * period, y = v * period;
  int cx = static_cast<int>(std::floor(x)), cy = static_cast<int>(std::floor(y));
  double best = 9;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      int nx = cx + dx, ny = cy + dy;
      double px = nx + latticeValue(nx, ny, period, seed), py = ny + latticeValue(nx, ny, period, seed + 7u);
      best = std::min(best, std::hypot(px - x, py - y));
    }
  return best;
}

std::uint8_t quantise(double x) {
  x = std::min(std::max(x, 0.0), 1.0);
  return static_cast<std::uint8_t>(std::lround(x * 255.0));
}

template <class F>
TextureImage generate(F texel) {
  TextureImage img;
  img.width = img.height = kSize;
  img.rgba.resize(kSize * kSize * 4);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      double u = (x + 0.5) / kSize, v = (y + 0.5) / kSize;
      double rgba[4] = {0, 0, 0, 1};
      texel(u, v, rgba);
      for (int c = 0; c < 4; ++c) img.rgba[(static_cast<size_t>(y) * kSize + static_cast<size_t>(x)) * 4 + static_cast<size_t>(c)] = quantise(rgba[c]);
    }
  return img;
}

// One case per row of builtinTextureTable() (-Wswitch names a missing one).
std::optional<TextureImage> makeBuiltinTexture(std::string_view name) {
  auto id = parseBuiltinTexture(name);
  if (!id) return std::nullopt;
  switch (*id) {
    case BuiltinTexture::Height:
      return generate([](double u, double v, double* o) { o[0] = o[1] = o[2] = fbm(u, v, 11u); });
    case BuiltinTexture::WaterNormal:
      // Tangent-space normal (z up, in blue) of a gentle fbm height field, by central
      // differences one texel apart, encoded as n * 0.5 + 0.5.
      return generate([](double u, double v, double* o) {
        const double e = 1.0 / kSize, strength = 6.0;
        double hx = fbm(u + e, v, 23u) - fbm(u - e, v, 23u);
        double hy = fbm(u, v + e, 23u) - fbm(u, v - e, 23u);
        double nx = -hx * strength, ny = -hy * strength, nz = 1.0;
        double len = std::sqrt(nx * nx + ny * ny + nz * nz);
        o[0] = nx / len * 0.5 + 0.5;
        o[1] = ny / len * 0.5 + 0.5;
        o[2] = nz / len * 0.5 + 0.5;
      });
    case BuiltinTexture::Dudv:
      return generate([](double u, double v, double* o) {
        o[0] = fbm(u, v, 37u);
        o[1] = fbm(u, v, 41u);
        o[2] = 0.0;
      });
    case BuiltinTexture::Foam:
      // Bright cell borders (F1 near its maximum) broken up by fbm: foam streaks.
      return generate([](double u, double v, double* o) {
        double d = cellDistance(u, v, 16, 53u);
        double streak = std::pow(std::min(d / 0.75, 1.0), 3.0) * (0.5 + fbm(u, v, 59u));
        o[0] = o[1] = o[2] = streak;
      });
  }
  return std::nullopt;
}

}  // namespace

// Generating costs tens of milliseconds per texture (fbm in double per texel), and every
// Renderer built by an editor's preview would pay it again: the images are pure functions
// of their name, so each is made once per process.
std::optional<TextureImage> generateBuiltinTexture(std::string_view name) {
  static std::mutex mutex;
  static std::map<std::string, std::optional<TextureImage>, std::less<>> made;
  std::lock_guard<std::mutex> lock(mutex);
  auto it = made.find(name);
  if (it == made.end()) it = made.emplace(std::string(name), makeBuiltinTexture(name)).first;
  return it->second;
}

}  // namespace wg
