// The ocean readers' reference (nodes/ocean_reference.h).
#include "nodes/ocean_reference.h"

#include <cmath>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <vector>

namespace wg::nodes::oceanref {
namespace {

// One cascade's two maps at one loop fraction, texel (jx, jz) at jz * N + jx.
struct CascadeMaps {
  std::uint32_t tau = 0;
  std::vector<std::array<double, 4>> displacement, slopes;
};

struct RegisteredOcean {
  ocean::OceanSettings settings;
  std::vector<ocean::OceanCascade> cascades;                           // made on first use
  std::vector<std::deque<std::shared_ptr<const CascadeMaps>>> recent;  // per cascade, newest first
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
  return maps;
}

std::shared_ptr<const CascadeMaps> mapsAt(int id, int cascade, double time) {
  const std::uint32_t tau = ocean::loopFraction(time);
  std::lock_guard<std::mutex> lock(registryMutex());
  auto& reg = registry();
  if (id < 0 || static_cast<size_t>(id) >= reg.size()) throw std::logic_error("ocean reference: unknown ocean id");
  RegisteredOcean& o = *reg[static_cast<size_t>(id)];
  if (o.cascades.empty()) {
    for (size_t c = 0; c < o.settings.cascades.tileLengths.size(); ++c)
      o.cascades.push_back(ocean::initialCascade(o.settings.spectrum, o.settings.cascades, static_cast<int>(c)));
    o.recent.resize(o.cascades.size());
  }
  if (cascade < 0 || static_cast<size_t>(cascade) >= o.cascades.size())
    throw std::logic_error("ocean reference: cascade out of range");
  auto& recent = o.recent[static_cast<size_t>(cascade)];
  for (const auto& m : recent)
    if (m->tau == tau) return m;
  // The fields depend on t only through tau (core/ocean_fft_reference.h).
  auto maps = computeMaps(o.cascades[static_cast<size_t>(cascade)], time, o.settings.cascades.choppiness, tau);
  recent.push_front(maps);
  if (recent.size() > kTimesKept) recent.pop_back();
  return maps;
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

MapSample sampleCascade(int id, int cascade, double time, double x, double z) {
  auto maps = mapsAt(id, cascade, time);
  const ocean::OceanSettings& s = settingsOf(id);
  const int n = s.cascades.resolution;
  // The constant the shader multiplies by, rounded to float as its literal is.
  const double texelsPerMetre = static_cast<float>(n / s.cascades.tileLengths[static_cast<size_t>(cascade)]);
  MapSample out;
  if (!std::isfinite(x) || !std::isfinite(z)) return out;
  double u = x * texelsPerMetre, v = z * texelsPerMetre;
  if (!std::isfinite(u) || !std::isfinite(v)) return out;
  double bu = std::floor(u), bv = std::floor(v);
  double fu = u - bu, fv = v - bv;
  auto wrap = [n](double b) { return static_cast<int>(b - n * std::floor(b / n)) & (n - 1); };
  int x0 = wrap(bu), z0 = wrap(bv), x1 = (x0 + 1) & (n - 1), z1 = (z0 + 1) & (n - 1);
  auto at = [n](int jx, int jz) { return static_cast<size_t>(jz) * n + jx; };
  auto blend = [&](const std::vector<std::array<double, 4>>& m, std::array<double, 4>& result) {
    for (int c = 0; c < 4; ++c) {
      double bottom = m[at(x0, z0)][c] + (m[at(x1, z0)][c] - m[at(x0, z0)][c]) * fu;
      double top = m[at(x0, z1)][c] + (m[at(x1, z1)][c] - m[at(x0, z1)][c]) * fu;
      result[c] = bottom + (top - bottom) * fv;
    }
  };
  blend(maps->displacement, out.displacement);
  blend(maps->slopes, out.slopes);
  return out;
}

}  // namespace wg::nodes::oceanref
