// linearize_depth: depth-buffer value -> linear view depth for a perspective projection.

// The advanced shaders tutorial's 2nf / (f + n - z (f - n)) with z = 2d - 1, rewritten exactly as
// n / ((1 - d) + d n / f): no cancellation near d = 1, and f = inf (or 1e38) is the
// infinite-far-plane limit n / (1 - d). Guards: d clamped to [0, 1], near floored at 1e-6,
// far at near, and the denominator at n * 1e-30, so the sky (d = 1, f = inf) gives a large
// finite 1e30 instead of inf; the result never exceeds 1e30.
float wg_linearize_depth(float depth, vec2 near_far) {
  float n = max(near_far.x, 1e-6);
  float r = n / max(near_far.y, n);
  float d = clamp(depth, 0.0, 1.0);
  float denom = (1.0 - d) + d * r;
  return min(n / max(denom, n * 1e-30), 1e30);
}

// The same where the compiler proved depth in [0, 1] and near, far in [1e-6, 1e30] (value
// facts: gl_FragCoord.z or a depth texture, and the runtime's clamped camera_near_far).
// Then r = n / max(f, n) lies in (0, 1], the denominator (1 - d) + d r >= r > 0, and the
// result n / denominator <= n / r = max(f, n) <= 1e30: every floor and cap of
// wg_linearize_depth is dead, and the values are the same.
float wg_linearize_depth_known(float depth, vec2 near_far) {
  float n = near_far.x;
  float r = n / max(near_far.y, n);
  return n / ((1.0 - depth) + depth * r);
}

// The two forms above with their per-draw part computed apart, once per draw
// (near_far_ratio: n = max(near, 1e-6), r = n / max(f, n)): the same operations on the same
// values, so the same results.
float wg_linearize_depth_ratio(float depth, float n, float r) {
  float d = clamp(depth, 0.0, 1.0);
  float denom = (1.0 - d) + d * r;
  return min(n / max(denom, n * 1e-30), 1e30);
}
float wg_linearize_depth_ratio_known(float depth, float n, float r) { return n / ((1.0 - depth) + depth * r); }
