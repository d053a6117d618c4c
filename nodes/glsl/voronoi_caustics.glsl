// Voronoi caustics (the stylized water shader, section 6): bright lines where the Voronoi F1 is small,
// intensity (1 - d)^3 per layer.

// One layer: F1 clamped to [0, 1] before inverting, since F1 can exceed 1 (up to ~1.4 with
// full jitter) and 1 - F1 would then be a negative base; the cube is written as products,
// so no pow is involved at all.
float wg_voronoi_caustics_layer(vec2 p, float jitter, float phase, bool animated, bool full) {
  float d = clamp(wg_voronoi_f1(p, jitter, phase, animated, full), 0.0, 1.0);
  float m = 1.0 - d;
  return m * m * m;
}
