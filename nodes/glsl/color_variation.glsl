// color_variation: the top-down water plan's colour variation of the water body: sun-facing slopes warmer,
// a slow value-noise hue shift, troughs darker. Its value noise uses an integer hash
// (no fract(sin)), so the CPU reference reproduces the GPU's lattice values bit for bit.

// PCG hash of one uint (O'Neill's PCG, the RXS-M-XS output of Jarzynski and Olano 2020).
uint wg_color_variation_pcg(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// The lattice value of a cell, wrapped to a 256-cell period, as a float in [0, 1) with 24
// bits (exactly representable in float and double).
float wg_color_variation_cell(ivec2 cell) {
  uvec2 c = uvec2(cell & ivec2(255));
  uint h = wg_color_variation_pcg(c.x + wg_color_variation_pcg(c.y));
  return float(h >> 8u) * (1.0 / 16777216.0);
}

// Value noise in [0, 1): smoothstep-weighted bilinear blend of the four lattice values
// around p (the top-down water plan's valueNoise with an integer hash). Periodic over 256 units, so p is
// wrapped first: huge coordinates never overflow the int conversion, and a time drift
// wrapped to the same period moves the pattern without a seam.
float wg_color_variation_noise(vec2 p) {
  vec2 q = mod(p, 256.0);
  vec2 i = floor(q);
  vec2 f = q - i;
  vec2 u = f * f * (3.0 - 2.0 * f);
  ivec2 c = ivec2(i);
  float a = wg_color_variation_cell(c);
  float b = wg_color_variation_cell(c + ivec2(1, 0));
  float d = wg_color_variation_cell(c + ivec2(0, 1));
  float e = wg_color_variation_cell(c + ivec2(1, 1));
  return mix(mix(a, b, u.x), mix(d, e, u.x), u.y);
}

// The top-down water plan, section 5, for a y-up world (the plan's top-down x/y plane is our x/z plane):
// slope shift from the horizontal alignment of the normal with the sun (mix factor kept
// in [0, 1]), hue shift by the noise, trough darkening (1 - height) * trough with the
// height kept in [0, 1].
vec3 wg_color_variation(vec3 base, vec3 n, vec3 sun, float height, float noise, float slope_strength,
                        float noise_strength, float trough) {
  vec3 nn = wg_safe_normalize_vec3(n);
  vec3 ss = wg_safe_normalize_vec3(sun);
  float facing = dot(nn.xz, ss.xz);
  vec3 slope = mix(vec3(-0.03, -0.01, 0.03), vec3(0.03, 0.05, -0.02), clamp(facing * 0.5 + 0.5, 0.0, 1.0));
  vec3 hue = mix(vec3(-0.02, 0.02, 0.04), vec3(0.02, 0.04, -0.02), noise);
  float darken = (1.0 - clamp(height, 0.0, 1.0)) * trough;
  return (base + slope * slope_strength + hue * noise_strength) * (1.0 - darken);
}
