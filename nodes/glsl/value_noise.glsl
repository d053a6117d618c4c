// Value noise: hashed values on the integer lattice, blended with the cubic Hermite weight
// 3t^2 - 2t^3 (the top-down water plan's valueNoise, with the PCG hash of hash.glsl in place of its
// fract-based hash21). Output in [0, 1).

// The lattice value of an integer cell: the first hashed word as a float in [0, 1).
float wg_value_noise_lattice(uvec3 c) { return wg_hash_unit_float(wg_hash_pcg3d(c).x); }

// 2D value noise; the cell is hashed as (x, y, 0), so it agrees with the hash node.
float wg_value_noise_vec2(vec2 p) {
  vec2 i = floor(p);
  vec2 f = p - i;
  uvec2 c = wg_hash_cell_vec2(p);
  vec2 u = f * f * (3.0 - 2.0 * f);
  float a = wg_value_noise_lattice(uvec3(c, 0u));
  float b = wg_value_noise_lattice(uvec3(c + uvec2(1u, 0u), 0u));
  float d = wg_value_noise_lattice(uvec3(c + uvec2(0u, 1u), 0u));
  float e = wg_value_noise_lattice(uvec3(c + uvec2(1u, 1u), 0u));
  return mix(mix(a, b, u.x), mix(d, e, u.x), u.y);
}

// 3D value noise: trilinear blend of the 8 hashed corners with Hermite weights.
float wg_value_noise_vec3(vec3 p) {
  vec3 i = floor(p);
  vec3 f = p - i;
  uvec3 c = wg_hash_cell_vec3(p);
  vec3 u = f * f * (3.0 - 2.0 * f);
  float v000 = wg_value_noise_lattice(c);
  float v100 = wg_value_noise_lattice(c + uvec3(1u, 0u, 0u));
  float v010 = wg_value_noise_lattice(c + uvec3(0u, 1u, 0u));
  float v110 = wg_value_noise_lattice(c + uvec3(1u, 1u, 0u));
  float v001 = wg_value_noise_lattice(c + uvec3(0u, 0u, 1u));
  float v101 = wg_value_noise_lattice(c + uvec3(1u, 0u, 1u));
  float v011 = wg_value_noise_lattice(c + uvec3(0u, 1u, 1u));
  float v111 = wg_value_noise_lattice(c + uvec3(1u, 1u, 1u));
  float z0 = mix(mix(v000, v100, u.x), mix(v010, v110, u.x), u.y);
  float z1 = mix(mix(v001, v101, u.x), mix(v011, v111, u.x), u.y);
  return mix(z0, z1, u.z);
}

// 2D value noise whose lattice repeats every (mask + 1) cells, mask + 1 a power of two:
// the cell is wrapped with a bitwise and, which also wraps negative cells correctly.
// Used where a time offset is wrapped to the same period (crest_foam), so the pattern
// drifts seamlessly at any time.
float wg_value_noise_tiled_vec2(vec2 p, uint mask) {
  vec2 i = floor(p);
  vec2 f = p - i;
  uvec2 c = wg_hash_cell_vec2(p);
  uvec2 c1 = (c + uvec2(1u)) & uvec2(mask);
  c = c & uvec2(mask);
  vec2 u = f * f * (3.0 - 2.0 * f);
  float a = wg_value_noise_lattice(uvec3(c.x, c.y, 0u));
  float b = wg_value_noise_lattice(uvec3(c1.x, c.y, 0u));
  float d = wg_value_noise_lattice(uvec3(c.x, c1.y, 0u));
  float e = wg_value_noise_lattice(uvec3(c1.x, c1.y, 0u));
  return mix(mix(a, b, u.x), mix(d, e, u.x), u.y);
}
