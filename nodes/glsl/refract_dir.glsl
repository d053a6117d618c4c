// refract_dir: Snell refraction of the view ray through the water surface (the advanced shaders tutorial's
// refract(-V, N, n1/n2)), with total internal reflection handled explicitly.

// The refracted direction of the ray -V through a surface whose normal N faces the viewer;
// eta = n_viewer / n_other (1/1.333 from air, 1.333 from water). The cosine of incidence is
// clamped to [0, 1] so grazing and back-facing views stay finite. When k = 1 - eta^2 (1 - c^2)
// < 0 no refracted ray exists (total internal reflection, from below past the critical
// angle): the mirror reflection 2cN - V is returned instead, with w = 1; otherwise w = 0.
// k is formed as eta^2 (c^2 - cos_c^2) from eta2 = eta^2 and cosCrit2 = 1 - 1/eta^2 (the
// critical angle's squared cosine), both formed in double by the compiler: near the
// critical angle the difference of squares is exact in float32 where 1 - eta^2 (1 - c^2)
// cancels after two roundings (see wg_transmitted_cos in fresnel.glsl).
vec4 wg_refract_dir(vec3 n, vec3 v, float eta, float eta2, float cosCrit2) {
  vec3 nn = wg_safe_normalize_vec3(n);
  vec3 vv = wg_safe_normalize_vec3(v);
  float c = clamp(dot(nn, vv), 0.0, 1.0);
  float k = eta2 * (c * c - cosCrit2);
  if (k < 0.0) return vec4(wg_safe_normalize_vec3(2.0 * c * nn - vv), 1.0);
  return vec4(wg_safe_normalize_vec3(-eta * vv + (eta * c - sqrt(k)) * nn), 0.0);
}
