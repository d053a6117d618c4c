// reflect_dir: the mirror direction of the view ray about the surface normal, for
// reflection look-ups (cube map, sky colour, screen-space reflection).

// GLSL reflect() of the incident ray -V about N. Both inputs are normalised safely first
// and the result once more, so it is a unit vector even for unnormalised inputs, and the
// zero vector (never NaN) when both inputs are zero.
vec3 wg_reflect_dir(vec3 n, vec3 v) {
  vec3 nn = wg_safe_normalize_vec3(n);
  vec3 vv = wg_safe_normalize_vec3(v);
  return wg_safe_normalize_vec3(reflect(-vv, nn));
}
