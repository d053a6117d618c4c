// Integer hashing for the noise nodes: PCG3D (Jarzynski and Olano, "Hash Functions for GPU
// Rendering", JCGT 2020) on the integer cell of a coordinate. Only uint arithmetic (wrapping
// multiply, add, xor, shift), so the GPU and the CPU reference (nodes/noise_reference.cpp)
// produce the same bits; no fract(sin(x) * k), whose result depends on each GPU's sin.

// The integer cell floor(p), clamped into the int range so the float -> int conversion is
// defined (2147483520 is the largest float below 2^31), then reinterpreted as uint (GLSL
// keeps the two's-complement bits, as the CPU's int32 -> uint32 conversion does).
uvec3 wg_hash_cell_vec3(vec3 p) {
  return uvec3(ivec3(clamp(floor(p), vec3(-2147483648.0), vec3(2147483520.0))));
}
uvec2 wg_hash_cell_vec2(vec2 p) {
  return uvec2(ivec2(clamp(floor(p), vec2(-2147483648.0), vec2(2147483520.0))));
}

// PCG3D: an LCG step per component, then two rounds of cross-component mixing around an
// xor-shift. All arithmetic wraps modulo 2^32.
uvec3 wg_hash_pcg3d(uvec3 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v ^= v >> 16u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  return v;
}

// The top 24 bits of each word as a float in [0, 1): float(h >> 8) is exact (< 2^24) and
// 2^-24 is a power of two, so the result is exactly representable in float32 and equal to
// the CPU's value bit for bit.
float wg_hash_unit_float(uint h) { return float(h >> 8u) * 5.9604644775390625e-8; }
vec3 wg_hash_unit_vec3(uvec3 h) { return vec3(h >> 8u) * 5.9604644775390625e-8; }

// Three hashed values in [0, 1) for the cell of p. A vec2 cell hashes as (x, y, 0).
vec3 wg_hash_vec2(vec2 p) { return wg_hash_unit_vec3(wg_hash_pcg3d(uvec3(wg_hash_cell_vec2(p), 0u))); }
vec3 wg_hash_vec3(vec3 p) { return wg_hash_unit_vec3(wg_hash_pcg3d(wg_hash_cell_vec3(p))); }
