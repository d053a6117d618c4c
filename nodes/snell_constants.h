#pragma once
// The constants of Snell's law that fresnel and refract_dir pass to their GLSL
// (wg_transmitted_cos, wg_refract_dir), formed in double here: the shader computes the
// transmitted cosine's square as eta2 (c^2 - cosCrit2), exact near the critical angle.
namespace wg::nodes {

struct SnellConstants {
  double eta2;      // eta^2, eta = n_incident / n_transmitted
  double cosCrit2;  // 1 - 1/eta^2: the squared cosine of the critical angle (negative for eta < 1)
};

inline SnellConstants snellConstants(double eta) {
  double eta2 = eta * eta;
  return {eta2, 1.0 - 1.0 / eta2};
}

}  // namespace wg::nodes
