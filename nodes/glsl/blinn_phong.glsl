// blinn_phong: specular highlight from the half vector (the advanced shaders tutorial, level 2).

// pow(max(N.H, 0), shininess) with H = normalize(L + V). When L = -V the half vector is
// zero and N.H = 0, so the highlight is 0 (the safe pow: 0^s = 0 for s > 0, 1 for s <= 0).
float wg_blinn_phong_specular(vec3 n, vec3 v, vec3 l, float shininess) {
  vec3 h = wg_safe_normalize_vec3(wg_safe_normalize_vec3(l) + wg_safe_normalize_vec3(v));
  float ndoth = clamp(dot(wg_safe_normalize_vec3(n), h), 0.0, 1.0);
  return wg_safe_pow_float(ndoth, shininess);
}
