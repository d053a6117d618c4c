// Edge foam (the advanced shaders tutorial and the stylized water shader): foam where the water is shallow, from a two-layer
// scrolling foam texture (the two samples are taken by the node; these shape them).

// Depth mask, the advanced shaders tutorial: 1 - smoothstep(0, width, depth); 1 at the edge, 0 from width on.
// A width <= 0 becomes a step at depth 0 (wg_smoothstep_float's equal edges).
float wg_edge_foam_mask_smooth(float depth, float width) {
  return 1.0 - wg_smoothstep_float(0.0, max(width, 0.0), depth);
}
// Depth mask, the stylized water shader: 1 - saturate(depth / width), width floored at 1e-6.
float wg_edge_foam_mask_linear(float depth, float width) {
  return 1.0 - clamp(depth / max(width, 1e-6), 0.0, 1.0);
}
// The stylized water shader's step(cutoff, texture * mask) * strength, softened over `softness` (0 gives the
// source's step; equal edges are defined by wg_smoothstep_float), limited to [0, 1].
float wg_edge_foam(float tex, float mask, float cutoff, float softness, float strength) {
  return clamp(strength * wg_smoothstep_float(cutoff, cutoff + max(softness, 0.0), tex * mask), 0.0, 1.0);
}
