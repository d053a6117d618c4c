// Texture caustics (the deferred water article, listing 14): two samples of a height texture scrolling in
// opposite directions; where they sum to 1 the light focuses.

// The caustic texture coordinates of a world point: (scale x + 0.5, 0.5 - scale z).
vec2 wg_texture_caustics_uv(vec3 pos, float scale) { return vec2(scale * pos.x + 0.5, 0.5 - scale * pos.z); }

// The focusing shape of the two samples: clamp(1 - |a + b - 1|, 0, 1)^9, the ninth power
// taken as two cubes (as the source does), so it needs no pow and the base is never negative.
float wg_texture_caustics_shape(float a, float b) {
  float c = clamp(1.0 - abs(a + b - 1.0), 0.0, 1.0);
  c *= c * c;
  c *= c * c;
  return c;
}
