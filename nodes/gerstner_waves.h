#pragma once
// The gerstner_waves node's wave list and double-precision reference, shared by its eval
// and its tests.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace wg::nodes {

inline constexpr double kGravity = 9.81;  // m/s^2, deep-water dispersion omega^2 = g k
inline constexpr int kMaxGerstnerWaves = 16;

struct GerstnerWave {
  double dirX = 1, dirZ = 0;  // unit direction
  double steepness = 0;       // Q
  double wavelength = 1;      // metres
  double k = 0;               // 2 pi / wavelength
  double omega = 0;           // sqrt(g k)
  double amplitude = 0;       // metres (default Q / k)
  double phase = 0;           // radians
};

// "" when valid; otherwise why not (the option's validate).
std::string validateGerstnerWaves(const nlohmann::json& v);
// A validated option value to waves (directions normalised, defaults filled in).
std::vector<GerstnerWave> parseGerstnerWaves(const nlohmann::json& v);

struct GerstnerFrame {
  double displacement[3] = {0, 0, 0};
  double dPdx[3] = {0, 0, 0};  // partial derivatives of the displaced point, not normalised
  double dPdz[3] = {0, 0, 0};
  double normal[3] = {0, 1, 0};  // unit, oriented up (up when degenerate)
};

// The sums at the undisplaced point (x, z) and time t, as the GLSL computes them.
GerstnerFrame gerstnerReference(const std::vector<GerstnerWave>& waves, double x, double z, double time);

}  // namespace wg::nodes
