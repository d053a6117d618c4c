// refract_dir: Snell refraction of the view ray through the water surface (the advanced shaders tutorial's
// refract(-V, N, n1/n2)), with total internal reflection handled explicitly.

// The refracted direction of the ray -V through a surface whose normal N faces the viewer;
// eta = n_viewer / n_other (1/1.333 from air, 1.333 from water). The cosine of incidence is
// clamped to [0, 1] so grazing and back-facing views stay finite. When 1 - eta^2 (1 - c^2)
// < 0 no refracted ray exists (total internal reflection, from below past the critical
// angle): the mirror reflection 2cN - V is returned instead, with w = 1; otherwise w = 0.
vec4 wg_refract_dir(vec3 n, vec3 v, float eta) {
  vec3 nn = wg_safe_normalize_vec3(n);
  vec3 vv = wg_safe_normalize_vec3(v);
  float c = clamp(dot(nn, vv), 0.0, 1.0);
  float k = 1.0 - eta * eta * (1.0 - c * c);
  if (k < 0.0) return vec4(wg_safe_normalize_vec3(2.0 * c * nn - vv), 1.0);
  return vec4(wg_safe_normalize_vec3(-eta * vv + (eta * c - sqrt(k)) * nn), 0.0);
}
