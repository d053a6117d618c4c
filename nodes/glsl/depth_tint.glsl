// Water colour by depth: shallow colour at the surface, deep colour from max_depth down.
// Negative thickness (scene in front of the water) counts as 0; max_depth is floored so it
// never divides by zero.
float wg_depth_tint_linear(float depth, float max_depth) {
  return clamp(depth / max(max_depth, 1e-6), 0.0, 1.0);
}
float wg_depth_tint_smooth(float depth, float max_depth) {
  return wg_smoothstep_float(0.0, max(max_depth, 1e-6), depth);
}

// The linear ramp where max_depth >= 1e-6 is proven (value facts: a parameter whose min is
// at least that): the floor is dead.
float wg_depth_tint_linear_floored(float depth, float max_depth) { return clamp(depth / max_depth, 0.0, 1.0); }
