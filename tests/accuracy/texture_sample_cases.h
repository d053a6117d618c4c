#pragma once
// The probe cases of the texture_sample GPU tests (GL in texture_sample_probe_test.cpp, WebGPU
// in wgsl_probe_test.cpp), for a 16x16 texture: uv on texel centres and edges, outside [0, 1]
// both ways, and for a mipmapped texture uv gradients selecting mip levels 0 to 4 and blends
// between them; and the worst error of a report.
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "accuracy/probe.h"

namespace wg::test {

// The cases: (u, v) and, for the mipmapped runs, the gradient (du/dx = dv/dy, the others
// zero: rho = 16 g, lambda = log2(16 g)).
inline std::string textureSampleCasesJson(bool gradients) {
  const double uvs[][2] = {{0.3, 0.6},       {0.5, 0.5},     {0.25, 0.75},   {1.0 / 32, 3.0 / 32}, {0.0, 0.0},
                           {1.0, 1.0},       {-0.05, 0.47},  {1.05, -0.21},  {-0.3, -1.7},         {2.61, 3.13},
                           {-7.77, 5.55},    {0.999, 0.001}, {0.123, 0.877}, {100.37, -50.21}};
  // lambda -1, 0.5, 1, 1.5, 2.32, 3, 4, 6: magnification, blends, single levels, past the last.
  const double gs[] = {1.0 / 32, std::sqrt(2.0) / 16, 2.0 / 16, std::sqrt(8.0) / 16, 5.0 / 16, 8.0 / 16, 1.0, 4.0};
  nlohmann::json cases = nlohmann::json::array();
  for (const auto& uv : uvs) {
    if (!gradients) {
      cases.push_back({{"name", "uv " + std::to_string(uv[0]) + " " + std::to_string(uv[1])}, {"uv", {uv[0], uv[1]}}});
      continue;
    }
    for (double g : gs)
      cases.push_back({{"name", "uv " + std::to_string(uv[0]) + " " + std::to_string(uv[1]) + " g " + std::to_string(g)},
                       {"uv", {uv[0], uv[1]}},
                       {"uv_dx", {g, 0}},
                       {"uv_dy", {0, g}}});
  }
  return nlohmann::json{{"cases", cases}}.dump();
}

// The largest |gpu - reference| over every case and component of a probe report.
inline double worstAbsError(const accuracy::ProbeReport& report) {
  double worst = 0;
  for (const auto& c : report.cases)
    for (int k = 0; k < c.components; ++k)
      worst = std::max(worst, std::abs(c.gpu[static_cast<size_t>(k)] - c.reference[static_cast<size_t>(k)]));
  return worst;
}

}  // namespace wg::test
