// The advanced shaders tutorial's procedural wave normals from layered sines ("Approach 1"): a flat up normal
// tilted by three layers of products of sines, large and slow to small and fast. Each
// argument is a spatial part, wrapped to [0, 2 pi) so sin stays accurate at 1e5 m, plus a
// time phase mod(omega t, 2 pi) computed in double on the CPU.

// Wraps a spatial phase to [0, 2 pi).
float wg_sine_normals_wrap(float x) { return mod(x, 6.283185307179586); }

// Layer 1 (large, slow): (sin(0.5 x + 0.8 t) cos(0.3 z + 0.6 t) * 0.3, cos(0.5 x + 0.8 t) * 0.2).
vec2 wg_sine_normals_layer1(vec2 p, float ph08, float ph06) {
  float a = wg_sine_normals_wrap(0.5 * p.x) + ph08;
  float w = sin(a) * cos(wg_sine_normals_wrap(0.3 * p.y) + ph06);
  return vec2(w * 0.3, cos(a) * 0.2);
}

// Layer 2 (medium): (sin(2 x + 1.5 z + 2 t) * 0.15, cos(1.5 x - 2 z + 1.8 t) * 0.1).
vec2 wg_sine_normals_layer2(vec2 p, float ph20, float ph18) {
  float w = sin(wg_sine_normals_wrap(2.0 * p.x + 1.5 * p.y) + ph20);
  return vec2(w * 0.15, cos(wg_sine_normals_wrap(1.5 * p.x - 2.0 * p.y) + ph18) * 0.1);
}

// Layer 3 (fine ripples): w = sin(8 x - 3 t) sin(6 z + 2.5 t); (w * 0.05, w * 0.05).
vec2 wg_sine_normals_layer3(vec2 p, float ph30, float ph25) {
  float w = sin(wg_sine_normals_wrap(8.0 * p.x) - ph30) * sin(wg_sine_normals_wrap(6.0 * p.y) + ph25);
  return vec2(w * 0.05, w * 0.05);
}
