// Coastal foam (the deferred water article, listing 13): shallow-water foam times a foam texture whose
// coordinates the surface normal distorts; foam also dims the specular highlight.

// The foam texture coordinates: (scale x + 0.5, 0.5 - scale z) + distortion (N.x, N.z).
vec2 wg_coastal_foam_uv(vec3 pos, vec3 normal, float scale, float distortion) {
  return vec2(scale * pos.x + 0.5, 0.5 - scale * pos.z) + distortion * normal.xz;
}
// How much foam before the texture: max(intensity (1 - d / max_depth), crest, 0), with
// d / max_depth clamped to [0, 1] (negative depth counts as the shoreline, the sky's
// depth as deep water; max_depth floored at 1e-6).
float wg_coastal_foam_amount(float depth, float max_depth, float intensity, float crest) {
  float r = clamp(depth / max(max_depth, 1e-6), 0.0, 1.0);
  return max(max(0.0, intensity * (1.0 - r)), crest);
}
// Specular dimming, the deferred water article: clamp(1 - k foam, 0, 1)^3.
float wg_coastal_foam_specular_cubic(float foam, float k) {
  float s = clamp(1.0 - k * foam, 0.0, 1.0);
  return s * s * s;
}
// Specular dimming, linear: clamp(1 - k foam, 0, 1).
float wg_coastal_foam_specular_linear(float foam, float k) { return clamp(1.0 - k * foam, 0.0, 1.0); }
