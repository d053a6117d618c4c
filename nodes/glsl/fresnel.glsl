// Fresnel reflectance of the water surface. `cosi` is the cosine between the unit normal
// (facing the viewer) and the unit view vector, clamped to [0, 1] by the caller, so
// grazing and back-facing views stay finite.

// Cosine of incidence, kept in [0, 1].
float wg_cos_incidence(vec3 n, vec3 v) { return clamp(dot(n, v), 0.0, 1.0); }

// The transmitted angle's cosine for eta = n_incident / n_transmitted, which exists only
// inside the critical angle; beyond it the reflection is total. Snell's law gives
// cos_t^2 = 1 - eta^2 (1 - cos_i^2); it is formed as eta^2 (cos_i^2 - cos_c^2), where
// eta2 = eta^2 and cosCrit2 = cos_c^2 = 1 - 1/eta^2 (the critical angle's squared cosine,
// negative from the less dense side, where there is none) are formed in double by the
// compiler. Near the critical angle cos_i^2 - cos_c^2 subtracts two close numbers, which
// float32 does exactly, where 1 - eta^2 (1 - cos_i^2) cancels after two roundings: a tenth
// of the error there (docs/accuracy.md). Returns -1 for total internal reflection (k <= 0).
float wg_transmitted_cos(float cosi, float eta2, float cosCrit2) {
  float k = eta2 * (cosi * cosi - cosCrit2);
  return k <= 0.0 ? -1.0 : sqrt(k);
}

// Schlick (1994): F0 + (1 - F0)(1 - cos)^5, with cos taken in the less dense medium.
float wg_fresnel_schlick(float cosi, float f0) {
  float m = 1.0 - cosi;
  float m2 = m * m;
  return f0 + (1.0 - f0) * m2 * m2 * m;
}
float wg_fresnel_schlick_from_below(float cosi, float f0, float eta2, float cosCrit2) {
  float cost = wg_transmitted_cos(cosi, eta2, cosCrit2);
  return cost < 0.0 ? 1.0 : wg_fresnel_schlick(cost, f0);
}

// Exact unpolarised dielectric Fresnel: the mean of the s and p reflectances, 1 under
// total internal reflection. n1 is the viewer's medium, n2 the other; eta2 = (n1/n2)^2 and
// cosCrit2 as for wg_transmitted_cos.
float wg_fresnel_exact(float cosi, float n1, float n2, float eta2, float cosCrit2) {
  float cost = wg_transmitted_cos(cosi, eta2, cosCrit2);
  if (cost < 0.0) return 1.0;
  float rs = (n1 * cosi - n2 * cost) / (n1 * cosi + n2 * cost);
  float rp = (n1 * cost - n2 * cosi) / (n1 * cost + n2 * cosi);
  return 0.5 * (rs * rs + rp * rp);
}

// Artistic power forms. The classic WebGL water renderer mixes reflection and refraction by (N.V)^strength, so its
// reflectance is 1 - (N.V)^strength; the stylized water shader uses (1 - N.V)^strength directly.
float wg_fresnel_power_cos(float cosi, float strength) { return 1.0 - wg_safe_pow_float(cosi, strength); }
float wg_fresnel_power_rim(float cosi, float strength) { return wg_safe_pow_float(1.0 - cosi, strength); }

// The power forms where strength > 0 is proven (value facts): cosi and 1 - cosi lie in
// [0, 1], so native pow is defined and equals the safe one.
float wg_fresnel_power_cos_positive(float cosi, float strength) { return 1.0 - pow(cosi, strength); }
float wg_fresnel_power_rim_positive(float cosi, float strength) { return pow(1.0 - cosi, strength); }
