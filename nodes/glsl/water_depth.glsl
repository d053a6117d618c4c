// water_depth: how much water lies between the surface and the scene behind it.

// The factor that turns a view-depth difference into a distance along the view ray:
// 1 / cos(ray, camera forward). The forward axis is -(row 2) of the view matrix; the
// cosine is floored at 0.1 (rays up to 84 degrees off-axis), and a degenerate (zero)
// view matrix counts as a ray along the axis (factor 1). Chosen with ?: between computed
// values rather than an early return, so it compiles to a select, not branches.
float wg_water_depth_ray_factor(mat4 view, vec3 v) {
  vec3 fwd = -vec3(view[0][2], view[1][2], view[2][2]);
  float c = dot(-wg_safe_normalize_vec3(v), wg_safe_normalize_vec3(fwd));
  float factor = 1.0 / max(c, 0.1);
  return dot(fwd, fwd) < 0.5 ? 1.0 : factor;
}

// Thickness of water from linear depths: scene minus surface, negative (scene in front of
// the water) clamped to 0, times the ray factor, and for the vertical measure times |V.y|
// (the vertical drop along the ray: exact for a straight ray, ignoring refraction).
// Kept <= 1e30, so the sky stays finite.
float wg_water_depth_thickness(float scene_linear, float surface_linear, float factor, float vertical) {
  return min(max(scene_linear - surface_linear, 0.0) * factor * vertical, 1e30);
}

// The ray factor where v is proven normalized (value facts: the safe-normalised view
// direction): re-normalising it changes nothing, so only the camera axis is normalised.
float wg_water_depth_ray_factor_unit_view(mat4 view, vec3 v) {
  vec3 fwd = -vec3(view[0][2], view[1][2], view[2][2]);
  float c = dot(-v, wg_safe_normalize_vec3(fwd));
  float factor = 1.0 / max(c, 0.1);
  return dot(fwd, fwd) < 0.5 ? 1.0 : factor;
}
