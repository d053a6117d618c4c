// Two scrolling samples of a tangent-space normal map, blended (the advanced shaders tutorial and the stylized water shader).

// The layer's texture coordinate: uv * scale + scroll, where scroll = fract(speed * time)
// is computed once per draw by ops of its own (the node's derived inputs). The texture
// repeats, so the offset is wrapped to [0, 1) and stays small at t = 1e6 s.
vec2 wg_normal_map_scroll_uv(vec2 uv, float scale, vec2 scroll) {
  return uv * scale + scroll;
}

// A texel to a tangent-space vector in [-1, 1]^3 (x along T, y along B, z along N).
vec3 wg_normal_map_scroll_unpack(vec4 texel) { return texel.xyz * 2.0 - 1.0; }

// Linear blend of the two sources: normalize(a + b).
vec3 wg_normal_map_scroll_add(vec3 a, vec3 b) { return wg_safe_normalize_vec3(a + b); }

// Whiteout blend: normalize(vec3(a.xy + b.xy, a.z * b.z)), keeps both layers' detail.
vec3 wg_normal_map_scroll_whiteout(vec3 a, vec3 b) { return wg_safe_normalize_vec3(vec3(a.xy + b.xy, a.z * b.z)); }

// Reoriented normal mapping (Barre-Brisebois and Hill 2012): b rotated by the rotation
// that takes +z to a. t.z is floored at 1e-6 so a base normal pointing down stays finite.
vec3 wg_normal_map_scroll_rnm(vec3 a, vec3 b) {
  vec3 t = a + vec3(0.0, 0.0, 1.0);
  vec3 u = b * vec3(-1.0, -1.0, 1.0);
  return wg_safe_normalize_vec3(t * dot(t, u) / max(t.z, 1e-6) - u);
}

// The blended tangent-space normal with its slope scaled by `strength`.
vec3 wg_normal_map_scroll_strength(vec3 n, float strength) { return vec3(n.xy * strength, n.z); }
