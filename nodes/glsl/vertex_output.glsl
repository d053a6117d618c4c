// Distance-based tessellation factor of the stylized water shader: full detail up to min_distance from the
// camera, falling linearly to 1% of it at max_distance, never below one segment. The
// distance range is floored so equal distances cannot divide by zero.
float wg_tess_distance_factor(vec3 p, vec3 camera, float min_distance, float max_distance, float factor) {
  float d = distance(p, camera);
  float f = clamp(1.0 - (d - min_distance) / max(max_distance - min_distance, 1e-6), 0.01, 1.0);
  return max(f * factor, 1.0);
}
