// near_far_ratio: the per-draw constants of a depth linearisation (linearize_depth.glsl).

// The near plane floored at 1e-6, where nothing proves it already is (a probe's near/far).
float wg_near_far_floor(vec2 near_far) { return max(near_far.x, 1e-6); }

// r = n / max(f, n) for n >= 1e-6: in [0, 1]; f = inf gives 0, f <= n gives 1.
float wg_near_far_ratio(float n, float far_plane) { return n / max(far_plane, n); }
