// phong_specular: the deferred water article's Phong specular of the sun and of the environment light.

// The deferred water article, listing 9: the light direction L mirrored about N, R = 2(N.L)N - L, against
// the unit direction to the viewer: max(R.V, 0), kept in [0, 1]. (Equal to
// max(dot(reflect(-V, N), L), 0), the view ray reflected against the light.)
float wg_phong_specular_lobe(vec3 n, vec3 v, vec3 l) {
  vec3 nn = wg_safe_normalize_vec3(n);
  vec3 ll = wg_safe_normalize_vec3(l);
  vec3 r = 2.0 * dot(nn, ll) * nn - ll;
  return clamp(dot(r, wg_safe_normalize_vec3(v)), 0.0, 1.0);
}

// The lobe where n, v and l are proven normalized (value facts: unit length or exactly
// zero, e.g. the safe-normalised builtins or a normal map's unit output): safe
// normalisation leaves such vectors unchanged, so it is left out. Same values, bounded
// (|r| <= 3) and clamped to [0, 1].
float wg_phong_specular_lobe_unit(vec3 n, vec3 v, vec3 l) {
  vec3 r = 2.0 * dot(n, l) * n - l;
  return clamp(dot(r, v), 0.0, 1.0);
}
