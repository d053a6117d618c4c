// water_depth: how much water lies between the surface and the scene behind it.

// The factor that turns a view-depth difference into a distance along the view ray:
// 1 / cos(ray, camera forward), from the unit camera axis (camera_forward, computed once
// per draw: -(row 2) of the view matrix, normalised) and the unit direction v towards the
// viewer. The cosine is floored at 0.1 (rays up to 84 degrees off-axis); a degenerate view
// matrix, whose axis camera_forward gives as zero, counts as a ray along the axis (factor
// 1). Chosen with ?: between computed values, so it compiles to a select, not branches.
float wg_water_depth_ray_factor_axis(vec3 axis, vec3 v) {
  float factor = 1.0 / max(dot(-v, axis), 0.1);
  return dot(axis, axis) < 0.25 ? 1.0 : factor;
}

// Thickness of water from linear depths: scene minus surface, negative (scene in front of
// the water) clamped to 0, times the ray factor, and for the vertical measure times |V.y|
// (the vertical drop along the ray: exact for a straight ray, ignoring refraction).
// Kept <= 1e30, so the sky stays finite.
float wg_water_depth_thickness(float scene_linear, float surface_linear, float factor, float vertical) {
  return min(max(scene_linear - surface_linear, 0.0) * factor * vertical, 1e30);
}
