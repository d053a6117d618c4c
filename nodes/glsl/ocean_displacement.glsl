// The spectral ocean's readers (ocean_displacement, ocean_surface): its maps at a world point.

// One ocean map (RGBA32F, n x n texels; texel (j, i) holds the field at x = j L / n,
// z = i L / n, repeating every L) at the world point xz, bilinear between the four texels
// around it. Four fetches rather than one filtered look-up: filtering a 32-bit float
// texture needs OES_texture_float_linear on OpenGL ES and WebGL2, and a hardware filter
// may keep as few as 8 fractional bits of its weights. The texel index wraps exactly
// while it is below 2^24 (|x| below 2^24 L / n); beyond, the mask keeps it in range.
vec4 wg_ocean_map(highp sampler2D map, vec2 xz, float texelsPerMetre, int n) {
  vec2 u = xz * texelsPerMetre;
  vec2 base = floor(u);
  vec2 f = u - base;
  float size = float(n);
  ivec2 a = ivec2(base - size * floor(base / size)) & (n - 1);
  ivec2 b = (a + 1) & (n - 1);
  vec4 t00 = texelFetch(map, a, 0);
  vec4 t10 = texelFetch(map, ivec2(b.x, a.y), 0);
  vec4 t01 = texelFetch(map, ivec2(a.x, b.y), 0);
  vec4 t11 = texelFetch(map, b, 0);
  return mix(mix(t00, t10, f.x), mix(t01, t11, f.x), f.y);
}

// How much of a cascade of tile L a point at distance d from the camera keeps: 1 up to
// fadeTiles L, 0 from 2 fadeTiles L, a smoothstep between (a mesh or a pixel far away
// cannot carry waves that short). Not called when the fade is off.
float wg_ocean_fade(float d, float start) { return 1.0 - smoothstep(start, 2.0 * start, d); }

// The unit normal of the displaced surface x0 -> x0 + (l Dx, h, l Dz) from the summed
// maps: slopes = (dh/dx, dh/dz, l dDx/dx, l dDz/dz) and lDxz = l dDx/dz. It is
// cross(dP/dz, dP/dx) with dP/dx = (1 + l Dxx, hx, l Dxz), dP/dz = (l Dxz, hz, 1 + l Dzz),
// whose y is the Jacobian J: where the surface folds (J < 0) it faces down, the underside
// of the folded sheet. Up where the two tangents are parallel (J = 0 on a flat slope).
vec3 wg_ocean_normal(vec4 slopes, float lDxz) {
  float jx = 1.0 + slopes.z, jz = 1.0 + slopes.w;
  vec3 n = vec3(slopes.y * lDxz - jz * slopes.x, jx * jz - lDxz * lDxz, lDxz * slopes.x - slopes.y * jx);
  return wg_waves_unit_or_vec3(n, vec3(0.0, 1.0, 0.0));
}

// J = (1 + l dDx/dx)(1 + l dDz/dz) - (l dDx/dz)^2 of the summed maps: below 0 the
// surface has folded over itself (where whitecaps form).
float wg_ocean_jacobian(vec4 slopes, float lDxz) { return (1.0 + slopes.z) * (1.0 + slopes.w) - lDxz * lDxz; }
