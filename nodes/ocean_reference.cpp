// The ocean readers' reference (nodes/ocean_reference.h).
#include "nodes/ocean_reference.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <vector>

namespace wg::nodes::oceanref {
namespace {

using Texels = std::vector<std::array<double, 4>>;

// One cascade's two maps at one loop fraction, texel (jx, jz) at jz * N + jx, and the
// filtered reader's pyramids: slopes and moments, level l of (N >> l)^2 texels.
struct CascadeMaps {
  std::uint32_t tau = 0;
  Texels displacement, slopes;
  std::vector<Texels> slopeLevels, momentLevels;
};

// The next level of a pyramid: each texel the mean of the 2x2 below it, in double.
Texels boxHalf(const Texels& level, int n) {
  const int h = n / 2;
  Texels out(static_cast<size_t>(h) * h);
  for (int jz = 0; jz < h; ++jz)
    for (int jx = 0; jx < h; ++jx) {
      auto at = [&](int x, int z) { return level[static_cast<size_t>(z) * n + x]; };
      const auto a = at(2 * jx, 2 * jz), b = at(2 * jx + 1, 2 * jz), c = at(2 * jx, 2 * jz + 1), d = at(2 * jx + 1, 2 * jz + 1);
      for (int k = 0; k < 4; ++k) out[static_cast<size_t>(jz) * h + jx][k] = (a[k] + b[k] + c[k] + d[k]) / 4;
    }
  return out;
}

std::vector<Texels> pyramid(Texels level0, int n) {
  std::vector<Texels> levels;
  levels.push_back(std::move(level0));
  for (int size = n; size > 1; size /= 2) levels.push_back(boxHalf(levels.back(), size));
  return levels;
}

struct RegisteredOcean {
  ocean::OceanSettings settings;
  std::vector<ocean::OceanCascade> cascades;                           // made on first use
  std::vector<std::deque<std::shared_ptr<const CascadeMaps>>> recent;  // per cascade, newest first
  std::vector<std::deque<std::shared_ptr<const ocean::FoamMaps>>> recentFoam;
};

// A probe evaluates every pixel at one or a few times: a handful kept per
// cascade saves all but the first transform of each.
constexpr size_t kTimesKept = 4;

std::mutex& registryMutex() {
  static std::mutex m;
  return m;
}
std::vector<std::unique_ptr<RegisteredOcean>>& registry() {
  static std::vector<std::unique_ptr<RegisteredOcean>> r;
  return r;
}
std::map<std::string, int>& registryKeys() {
  static std::map<std::string, int> keys;
  return keys;
}

std::shared_ptr<const CascadeMaps> computeMaps(const ocean::OceanCascade& cascade, double time, double lambda,
                                               std::uint32_t tau) {
  ocean::OceanFields f = ocean::oceanFields(cascade, time, lambda);
  auto maps = std::make_shared<CascadeMaps>();
  maps->tau = tau;
  size_t count = f.height.size();
  maps->displacement.resize(count);
  maps->slopes.resize(count);
  for (size_t i = 0; i < count; ++i) {
    maps->displacement[i] = {lambda * f.displacementX[i], f.height[i], lambda * f.displacementZ[i],
                             lambda * f.dDxdz[i]};
    maps->slopes[i] = {f.slopeX[i], f.slopeZ[i], lambda * f.dDxdx[i], lambda * f.dDzdz[i]};
  }
  Texels moments(count);
  for (size_t i = 0; i < count; ++i) {
    const double sx = maps->slopes[i][0], sz = maps->slopes[i][1];
    moments[i] = {sx * sx, sz * sz, sx * sz, maps->displacement[i][3]};
  }
  maps->slopeLevels = pyramid(maps->slopes, cascade.resolution);
  maps->momentLevels = pyramid(std::move(moments), cascade.resolution);
  return maps;
}

// The registered ocean `id` with its cascades made, and the index of `cascade` checked;
// called with the registry's lock held.
RegisteredOcean& oceanWithCascade(int id, int cascade) {
  auto& reg = registry();
  if (id < 0 || static_cast<size_t>(id) >= reg.size()) throw std::logic_error("ocean reference: unknown ocean id");
  RegisteredOcean& o = *reg[static_cast<size_t>(id)];
  if (o.cascades.empty()) {
    for (size_t c = 0; c < o.settings.cascades.tileLengths.size(); ++c)
      o.cascades.push_back(ocean::initialCascade(o.settings.spectrum, o.settings.cascades, static_cast<int>(c)));
    o.recent.resize(o.cascades.size());
    o.recentFoam.resize(o.cascades.size());
  }
  if (cascade < 0 || static_cast<size_t>(cascade) >= o.cascades.size())
    throw std::logic_error("ocean reference: cascade out of range");
  return o;
}

template <class T, class Key, class Make>
std::shared_ptr<const T> cached(std::deque<std::shared_ptr<const T>>& recent, Key key, Key T::*field, Make make) {
  for (const auto& m : recent)
    if ((*m).*field == key) return m;
  auto made = make();
  recent.push_front(made);
  if (recent.size() > kTimesKept) recent.pop_back();
  return made;
}

std::shared_ptr<const CascadeMaps> mapsAt(int id, int cascade, double time) {
  const std::uint32_t tau = ocean::loopFraction(time);
  std::lock_guard<std::mutex> lock(registryMutex());
  RegisteredOcean& o = oceanWithCascade(id, cascade);
  // The fields depend on t only through tau (core/ocean_fft_reference.h).
  return cached(o.recent[static_cast<size_t>(cascade)], tau, &CascadeMaps::tau, [&] {
    return computeMaps(o.cascades[static_cast<size_t>(cascade)], time, o.settings.cascades.choppiness, tau);
  });
}

std::shared_ptr<const ocean::FoamMaps> foamAt(int id, int cascade, std::int64_t step) {
  std::lock_guard<std::mutex> lock(registryMutex());
  RegisteredOcean& o = oceanWithCascade(id, cascade);
  return cached(o.recentFoam[static_cast<size_t>(cascade)], step, &ocean::FoamMaps::step, [&] {
    return std::make_shared<const ocean::FoamMaps>(ocean::replayFoam(
        o.cascades[static_cast<size_t>(cascade)], o.settings.cascades.choppiness, o.settings.foam, step));
  });
}

// The four texels around the world point (x, z) of an N x N map of tile L and the
// weights between them, as wg_ocean_map takes them (the fragment stage's read); nothing for
// a point that is not finite.
struct Bilinear {
  size_t i00, i10, i01, i11;
  double fu, fv;
};
std::optional<Bilinear> bilinearAt(const ocean::OceanSettings& s, int cascade, double x, double z) {
  const int n = ocean::cascadeResolution(s.cascades, static_cast<size_t>(cascade));
  // The constant the shader multiplies by, rounded to float as its literal is.
  const double texelsPerMetre = static_cast<float>(n / s.cascades.tileLengths[static_cast<size_t>(cascade)]);
  if (!std::isfinite(x) || !std::isfinite(z)) return std::nullopt;
  double u = x * texelsPerMetre, v = z * texelsPerMetre;
  if (!std::isfinite(u) || !std::isfinite(v)) return std::nullopt;
  double bu = std::floor(u), bv = std::floor(v);
  auto wrap = [n](double b) { return static_cast<int>(b - n * std::floor(b / n)) & (n - 1); };
  int x0 = wrap(bu), z0 = wrap(bv), x1 = (x0 + 1) & (n - 1), z1 = (z0 + 1) & (n - 1);
  auto at = [n](int jx, int jz) { return static_cast<size_t>(jz) * n + jx; };
  return Bilinear{at(x0, z0), at(x1, z0), at(x0, z1), at(x1, z1), u - bu, v - bv};
}

// As bilinearAt at level `level` of the pyramid: wg_ocean_map_level's texel coordinate.
std::optional<Bilinear> levelBilinearAt(const ocean::OceanSettings& s, int cascade, double x, double z, int level) {
  const int n = ocean::cascadeResolution(s.cascades, static_cast<size_t>(cascade));
  const double texelsPerMetre = static_cast<float>(n / s.cascades.tileLengths[static_cast<size_t>(cascade)]);
  const int nl = n >> level;
  const double scale = std::ldexp(1.0, level);
  double u = (x * texelsPerMetre - 0.5 * (scale - 1)) / scale, v = (z * texelsPerMetre - 0.5 * (scale - 1)) / scale;
  if (!std::isfinite(u) || !std::isfinite(v)) return std::nullopt;
  double bu = std::floor(u), bv = std::floor(v);
  auto wrap = [nl](double b) { return static_cast<int>(b - nl * std::floor(b / nl)) & (nl - 1); };
  int x0 = wrap(bu), z0 = wrap(bv), x1 = (x0 + 1) & (nl - 1), z1 = (z0 + 1) & (nl - 1);
  auto at = [nl](int jx, int jz) { return static_cast<size_t>(jz) * nl + jx; };
  return Bilinear{at(x0, z0), at(x1, z0), at(x0, z1), at(x1, z1), u - bu, v - bv};
}

// The 4 x 4 texels of level 0 around the world point (x, z) and Catmull-Rom's weights
// between them, as wg_ocean_map_cubic takes them; nothing for a point that is not finite.
struct Bicubic {
  std::array<size_t, 4> columns, rows;  // texel indices jx, and row offsets jz * n
  std::array<double, 4> wx, wz;
};
std::array<double, 4> cubicWeights(double t) {
  const double t2 = t * t, t3 = t2 * t;
  return {t2 - 0.5 * (t + t3), 1.0 + 1.5 * t3 - 2.5 * t2, 0.5 * t + 2.0 * t2 - 1.5 * t3, 0.5 * (t3 - t2)};
}
std::optional<Bicubic> bicubicAt(const ocean::OceanSettings& s, int cascade, double x, double z) {
  const int n = ocean::cascadeResolution(s.cascades, static_cast<size_t>(cascade));
  const double texelsPerMetre = static_cast<float>(n / s.cascades.tileLengths[static_cast<size_t>(cascade)]);
  const double u = x * texelsPerMetre, v = z * texelsPerMetre;
  if (!std::isfinite(u) || !std::isfinite(v)) return std::nullopt;
  const double bu = std::floor(u), bv = std::floor(v);
  auto wrap = [n](double b) { return static_cast<int>(b - n * std::floor(b / n)) & (n - 1); };
  const int x0 = wrap(bu), z0 = wrap(bv);
  Bicubic c;
  for (int k = 0; k < 4; ++k) {
    c.columns[static_cast<size_t>(k)] = static_cast<size_t>((x0 + k + n - 1) & (n - 1));
    c.rows[static_cast<size_t>(k)] = static_cast<size_t>((z0 + k + n - 1) & (n - 1)) * static_cast<size_t>(n);
  }
  c.wx = cubicWeights(u - bu);
  c.wz = cubicWeights(v - bv);
  return c;
}
template <class Texel>
double blend(const Bicubic& c, Texel texel) {
  double sum = 0;
  for (size_t j = 0; j < 4; ++j) {
    double row = 0;
    for (size_t i = 0; i < 4; ++i) row += c.wx[i] * texel(c.rows[j] + c.columns[i]);
    sum += c.wz[j] * row;
  }
  return sum;
}

template <class Texel>
double blend(const Bilinear& b, Texel texel) {
  double bottom = texel(b.i00) + (texel(b.i10) - texel(b.i00)) * b.fu;
  double top = texel(b.i01) + (texel(b.i11) - texel(b.i01)) * b.fu;
  return bottom + (top - bottom) * b.fv;
}

}  // namespace

int registerOcean(const ocean::OceanSettings& settings) {
  std::string key = ocean::settingsKey(settings);
  std::lock_guard<std::mutex> lock(registryMutex());
  auto& keys = registryKeys();
  auto it = keys.find(key);
  if (it != keys.end()) return it->second;
  auto& reg = registry();
  auto o = std::make_unique<RegisteredOcean>();
  o->settings = settings;
  reg.push_back(std::move(o));
  int id = static_cast<int>(reg.size()) - 1;
  keys.emplace(std::move(key), id);
  return id;
}

const ocean::OceanSettings& settingsOf(int id) {
  std::lock_guard<std::mutex> lock(registryMutex());
  auto& reg = registry();
  if (id < 0 || static_cast<size_t>(id) >= reg.size()) throw std::logic_error("ocean reference: unknown ocean id");
  return reg[static_cast<size_t>(id)]->settings;
}

MapSample sampleCascade(int id, int cascade, double time, double x, double z, bool bicubic) {
  auto maps = mapsAt(id, cascade, time);
  MapSample out;
  auto read = [&](const auto& weights) {
    for (int c = 0; c < 4; ++c) {
      out.displacement[c] = blend(weights, [&](size_t i) { return maps->displacement[i][c]; });
      out.slopes[c] = blend(weights, [&](size_t i) { return maps->slopes[i][c]; });
    }
  };
  if (bicubic) {
    if (auto b = bicubicAt(settingsOf(id), cascade, x, z)) read(*b);  // as wg_ocean_map_cubic
  } else {
    if (auto b = bilinearAt(settingsOf(id), cascade, x, z)) read(*b);  // as wg_ocean_map
  }
  return out;
}

FilteredSample sampleCascadeFiltered(int id, int cascade, double time, double x, double z, double lod) {
  auto maps = mapsAt(id, cascade, time);
  const int levels = static_cast<int>(maps->slopeLevels.size()) - 1;
  FilteredSample out;
  if (!std::isfinite(lod)) return out;
  // As wg_ocean_map_lod: levels l0 and l0 + 1, l0 at most levels - 1.
  const int l0 = std::min(static_cast<int>(std::floor(lod)), levels - 1);
  const double f = lod - l0;
  std::array<FilteredSample, 2> at;
  for (int k = 0; k < 2; ++k) {
    auto b = levelBilinearAt(settingsOf(id), cascade, x, z, l0 + k);
    if (!b) return out;
    const Texels &s = maps->slopeLevels[static_cast<size_t>(l0 + k)], &m = maps->momentLevels[static_cast<size_t>(l0 + k)];
    for (int c = 0; c < 4; ++c) {
      at[k].slopes[c] = blend(*b, [&](size_t i) { return s[i][c]; });
      at[k].moments[c] = blend(*b, [&](size_t i) { return m[i][c]; });
    }
  }
  for (int c = 0; c < 4; ++c) {
    out.slopes[c] = at[0].slopes[c] + (at[1].slopes[c] - at[0].slopes[c]) * f;
    out.moments[c] = at[0].moments[c] + (at[1].moments[c] - at[0].moments[c]) * f;
  }
  return out;
}

const std::vector<std::array<double, 4>>& pyramidLevel(int id, int cascade, double time, bool moments, int level) {
  // The maps stay alive in the cache while the caller holds none of its own: keep the
  // last one asked for alive here (tests read one level at a time).
  static thread_local std::shared_ptr<const CascadeMaps> held;
  held = mapsAt(id, cascade, time);
  const auto& levels = moments ? held->momentLevels : held->slopeLevels;
  if (level < 0 || static_cast<size_t>(level) >= levels.size()) throw std::logic_error("ocean reference: no such pyramid level");
  return levels[static_cast<size_t>(level)];
}

double sampleFoam(int id, int cascade, double time, double x, double z) {
  const ocean::OceanSettings& s = settingsOf(id);
  if (!ocean::makesFoam(s, cascade)) return 0;
  const std::int64_t step = ocean::stepIndex(s.foam, time);
  auto foam = foamAt(id, cascade, step);
  auto b = bilinearAt(s, cascade, x, z);
  if (!b) return 0;
  // In time at each texel, then between the texels, as the simulation writes its map and
  // the shader reads it.
  const double fraction = ocean::foamFraction(s.foam, time);
  return blend(*b, [&](size_t i) { return foam->current[i] + (foam->next[i] - foam->current[i]) * fraction; });
}

}  // namespace wg::nodes::oceanref
