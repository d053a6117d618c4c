#include "nodes/rounded_intermediates.h"

#include <string>
#include <unordered_map>

namespace wg::nodes {

const RoundedIntermediates* roundedIntermediates(std::string_view nodeType) {
  static const std::unordered_map<std::string, RoundedIntermediates> table = {
      {"gerstner_waves", gerstnerRoundedIntermediates},
      {"voronoi_caustics", voronoiCausticsRoundedIntermediates},
  };
  auto it = table.find(std::string(nodeType));
  return it == table.end() ? nullptr : &it->second;
}

}  // namespace wg::nodes
