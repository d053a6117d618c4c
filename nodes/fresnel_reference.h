#pragma once
// The double-precision Fresnel formulas, shared by the fresnel node's eval and its tests.
#include <string>

namespace wg::nodes {

struct FresnelSetup {
  std::string model;   // schlick | exact | power
  bool fromBelow = false;
  double ior = 1.333;
  bool rim = false;    // power form (1 - c)^s instead of 1 - c^s
};

// Transmitted-angle cosine for eta = n_incident / n_transmitted; -1 under total reflection.
double transmittedCos(double cosi, double eta);
double fresnelExact(double cosi, double n1, double n2);
double fresnelSchlick(double cosi, double f0);
// `cosi` already clamped to [0, 1].
double fresnelReference(const FresnelSetup& s, double cosi, double f0, double strength);

}  // namespace wg::nodes
