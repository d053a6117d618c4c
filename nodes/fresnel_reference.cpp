#include "nodes/fresnel_reference.h"

#include <cmath>

#include "nodes/eval_math.h"

namespace wg::nodes {

double transmittedCos(double cosi, double eta) {
  double sin2t = eta * eta * (1.0 - cosi * cosi);
  return sin2t >= 1.0 ? -1.0 : std::sqrt(1.0 - sin2t);
}

double fresnelExact(double cosi, double n1, double n2) {
  double cost = transmittedCos(cosi, n1 / n2);
  if (cost < 0.0) return 1.0;
  double rs = (n1 * cosi - n2 * cost) / (n1 * cosi + n2 * cost);
  double rp = (n1 * cost - n2 * cosi) / (n1 * cost + n2 * cosi);
  return 0.5 * (rs * rs + rp * rp);
}

double fresnelSchlick(double cosi, double f0) {
  double m = 1.0 - cosi;
  return f0 + (1.0 - f0) * m * m * m * m * m;
}

double fresnelReference(const FresnelSetup& s, double c, double f0, double strength) {
  if (s.model == FresnelModel::Schlick) {
    if (!s.fromBelow) return fresnelSchlick(c, f0);
    double cost = transmittedCos(c, s.ior);
    return cost < 0.0 ? 1.0 : fresnelSchlick(cost, f0);
  }
  if (s.model == FresnelModel::Exact) return s.fromBelow ? fresnelExact(c, s.ior, 1.0) : fresnelExact(c, 1.0, s.ior);
  return s.rim ? glsl::safePow(1.0 - c, strength) : 1.0 - glsl::safePow(c, strength);
}

}  // namespace wg::nodes
