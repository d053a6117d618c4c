#pragma once
// The double-precision Fresnel formulas, shared by the fresnel node's eval and its tests.
namespace wg::nodes {

enum class FresnelModel { Schlick, Exact, Power };

// The fresnel node's options, parsed once (its defaults are in nodes/fresnel.cpp).
struct FresnelSetup {
  FresnelModel model;
  bool fromBelow;  // the viewer under water: total internal reflection past the critical angle
  double ior;
  bool rim;  // power form (1 - c)^s instead of 1 - c^s
};

// Transmitted-angle cosine for eta = n_incident / n_transmitted; -1 under total reflection.
double transmittedCos(double cosi, double eta);
double fresnelExact(double cosi, double n1, double n2);
double fresnelSchlick(double cosi, double f0);
// `cosi` already clamped to [0, 1].
double fresnelReference(const FresnelSetup& s, double cosi, double f0, double strength);

}  // namespace wg::nodes
