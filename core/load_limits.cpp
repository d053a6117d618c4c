#include "core/load_limits.h"

#include <cmath>
#include <vector>

#include <nlohmann/json.hpp>

namespace wg {

bool fitsFloat32(double x) { return std::isfinite(x) && std::fabs(x) <= kFloat32Max; }

std::string checkJsonLimits(const nlohmann::json& value, int depth) {
  // Iterative: the value may come from anywhere (a script), its depth is not known yet.
  std::vector<std::pair<const nlohmann::json*, int>> stack{{&value, depth}};
  while (!stack.empty()) {
    auto [v, level] = stack.back();
    stack.pop_back();
    if (v->is_string()) {
      if (v->get_ref<const std::string&>().size() > kMaxStringBytes)
        return "a string is longer than " + std::to_string(kMaxStringBytes) + " bytes";
    } else if (v->is_number_float()) {
      if (!fitsFloat32(v->get<double>())) return "a number is not finite in float32 range";
    } else if (v->is_array() || v->is_object()) {
      if (level + 1 > kMaxJsonDepth) return "it nests deeper than " + std::to_string(kMaxJsonDepth) + " levels in the file";
      for (auto it = v->begin(); it != v->end(); ++it) {
        if (v->is_object() && it.key().size() > kMaxStringBytes)
          return "a key is longer than " + std::to_string(kMaxStringBytes) + " bytes";
        stack.push_back({&*it, level + 1});
      }
    }
  }
  return "";
}

}  // namespace wg
