// Voronoi (cellular) noise: one feature point per integer cell, placed by the PCG hash of
// the cell (hash.glsl), so the pattern is the same on every GPU and on the CPU.

// 2 pi, for the per-cell phase offsets of the animated points.
const float WG_VORONOI_TAU = 6.283185307179586;

// Where a cell's point lies inside the cell, from the cell's hash h in [0, 1)^2.
// Static: 0.5 + jitter (h - 0.5). Animated: the point orbits the cell centre on a
// Lissajous-like loop, 0.5 + jitter/2 (sin(phase + 2 pi h.x), cos(phase + 2 pi h.y)); the
// phase is already wrapped to [0, 2 pi) by the caller. With jitter in [0, 1] the point
// never leaves its cell.
vec2 wg_voronoi_offset(vec2 h, float jitter, float phase, bool animated) {
  vec2 w = animated ? 0.5 * vec2(sin(phase + WG_VORONOI_TAU * h.x), cos(phase + WG_VORONOI_TAU * h.y)) : h - 0.5;
  return 0.5 + clamp(jitter, 0.0, 1.0) * w;
}

// F1 (distance to the nearest point), F2 (second nearest) and the nearest point's integer
// cell, as vec4(F1, F2, cell.x, cell.y). full = true searches the 3x3 cells around p
// (9 hashes); false searches only the 2x2 block on p's side of its cell (4 hashes): F1 is
// then approximate and F2 can be much too large. Distances are taken relative to p's cell,
// so they stay accurate at large coordinates; cells are stepped in uint (wrapping).
vec4 wg_voronoi(vec2 p, float jitter, float phase, bool animated, bool full) {
  vec2 cellf = floor(p);
  vec2 f = p - cellf;
  uvec2 cell = wg_hash_cell_vec2(p);
  ivec2 lo = full ? ivec2(-1) : ivec2(step(vec2(0.5), f)) - ivec2(1);
  int n = full ? 3 : 2;
  float f1 = 1e30;
  float f2 = 1e30;
  vec2 best = vec2(0.0);
  for (int j = 0; j < 3; ++j) {
    if (j >= n) break;
    for (int i = 0; i < 3; ++i) {
      if (i >= n) break;
      ivec2 o = lo + ivec2(i, j);
      vec2 h = wg_hash_unit_vec3(wg_hash_pcg3d(uvec3(cell + uvec2(o), 0u))).xy;
      vec2 q = vec2(o) + wg_voronoi_offset(h, jitter, phase, animated) - f;
      float d = sqrt(dot(q, q));
      if (d < f1) {
        f2 = f1;
        f1 = d;
        best = vec2(o);
      } else if (d < f2) {
        f2 = d;
      }
    }
  }
  return vec4(f1, f2, cellf + best);
}

// F1 alone (the distance to the nearest feature point), as wg_voronoi(...).x over the same
// cells (full: the 3x3 around p; else the 2x2 block on p's side of its cell): the nearest
// squared distance, one square root at the end (sqrt is monotonic and correctly rounded,
// so the value is the same), without F2 and the nearest cell, whose bookkeeping branches
// cost a caller that reads only F1 (the caustics) SPIR-V size and time (issue 10).
float wg_voronoi_f1(vec2 p, float jitter, float phase, bool animated, bool full) {
  vec2 f = p - floor(p);
  uvec2 cell = wg_hash_cell_vec2(p);
  ivec2 lo = full ? ivec2(-1) : ivec2(step(vec2(0.5), f)) - ivec2(1);
  int n = full ? 3 : 2;
  float d2 = 1e30;
  // Bounded by n itself (no break): with `full` a literal at every call, n is a constant
  // after inlining and the loops have a fixed trip count.
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      ivec2 o = lo + ivec2(i, j);
      vec2 h = wg_hash_unit_vec3(wg_hash_pcg3d(uvec3(cell + uvec2(o), 0u))).xy;
      vec2 q = vec2(o) + wg_voronoi_offset(h, jitter, phase, animated) - f;
      d2 = min(d2, dot(q, q));
    }
  }
  return sqrt(d2);
}
