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

// --- The filtered reader (ocean_surface's `filter`): the maps averaged over a pixel's
// footprint on the water, and the slope variance that averaging removes.

// The side of the square a pixel covers on the still water at p seen from `camera`, in
// metres: the pixel's angle times the distance, stretched along the view by 1 / cos theta
// (theta from the vertical), the footprint's longer axis as an isotropic GPU filter takes
// it; cos theta is held at 1/1024 or more (a grazing view gives a long, finite footprint).
float wg_ocean_footprint(vec3 p, vec3 camera, float pixelAngle) {
  vec3 v = p - camera;
  float d = length(v);
  float cosTheta = d > 0.0 ? abs(v.y) / d : 0.0;
  return d * pixelAngle / max(cosTheta, 1.0 / 1024.0);
}

// The level of detail of a map of `texelsPerMetre` for a footprint: log2 of the footprint
// in texels, 0 (the map itself) below one texel, at most `levels` (log2 n: the 1 x 1 mean).
float wg_ocean_lod(float footprint, float texelsPerMetre, int levels) {
  return clamp(log2(max(footprint * texelsPerMetre, 1.0)), 0.0, float(levels));
}

// Level `level` of a map pyramid (n >> level texels a side; its texel j the mean of texels
// j 2^l .. j 2^l + 2^l - 1 of level 0, centred at level-0 coordinate j 2^l + (2^l - 1) / 2)
// at the level-0 texel coordinate u, bilinear between its four texels as wg_ocean_map.
vec4 wg_ocean_map_level(highp sampler2D map, vec2 u, int n, int level) {
  float scale = float(1 << level);
  vec2 ul = (u - 0.5 * (scale - 1.0)) / scale;
  int nl = n >> level;
  vec2 base = floor(ul);
  vec2 f = ul - base;
  float size = float(nl);
  ivec2 a = ivec2(base - size * floor(base / size)) & (nl - 1);
  ivec2 b = (a + 1) & (nl - 1);
  vec4 t00 = texelFetch(map, a, level);
  vec4 t10 = texelFetch(map, ivec2(b.x, a.y), level);
  vec4 t01 = texelFetch(map, ivec2(a.x, b.y), level);
  vec4 t11 = texelFetch(map, b, level);
  return mix(mix(t00, t10, f.x), mix(t01, t11, f.x), f.y);
}

// Catmull-Rom's weights of the texels at -1, 0, 1 and 2 for the fraction t in [0, 1]: the
// cubic through the two middle texels with the central differences as its slopes. They sum
// to 1 and give the texel itself at t = 0.
vec4 wg_ocean_cubic_weights(float t) {
  float t2 = t * t;
  float t3 = t2 * t;
  return vec4(t2 - 0.5 * (t + t3), 1.0 + 1.5 * t3 - 2.5 * t2, 0.5 * t + 2.0 * t2 - 1.5 * t3, 0.5 * (t3 - t2));
}

// One row of the cubic read: the four texels xs of row z of level 0, weighted by w.
vec4 wg_ocean_cubic_row(highp sampler2D map, ivec4 xs, int z, vec4 w) {
  return w.x * texelFetch(map, ivec2(xs.x, z), 0) + w.y * texelFetch(map, ivec2(xs.y, z), 0) +
         w.z * texelFetch(map, ivec2(xs.z, z), 0) + w.w * texelFetch(map, ivec2(xs.w, z), 0);
}

// A map (n x n texels) at the world point xz, bicubic (Catmull-Rom) between the 4 x 4
// texels around it, wrapping as wg_ocean_map: the vertex stage's read (ocean_displacement).
// The mesh near the camera is finer than a long cascade's texels, whose waves span 10 texels
// or more: the cubic follows them to O(h^4) where a bilinear read errs by O(h^2), so that a
// coarser grid of the same waves moves the mesh by a tenth as much (docs/ocean.md).
vec4 wg_ocean_map_cubic(highp sampler2D map, vec2 xz, float texelsPerMetre, int n) {
  vec2 u = xz * texelsPerMetre;
  vec2 base = floor(u);
  vec2 f = u - base;
  float size = float(n);
  int m = n - 1;
  ivec2 a = ivec2(base - size * floor(base / size)) & m;
  ivec4 xs = ivec4((a.x + m) & m, a.x, (a.x + 1) & m, (a.x + 2) & m);
  ivec4 zs = ivec4((a.y + m) & m, a.y, (a.y + 1) & m, (a.y + 2) & m);
  vec4 wx = wg_ocean_cubic_weights(f.x);
  vec4 wz = wg_ocean_cubic_weights(f.y);
  return wz.x * wg_ocean_cubic_row(map, xs, zs.x, wx) + wz.y * wg_ocean_cubic_row(map, xs, zs.y, wx) +
         wz.z * wg_ocean_cubic_row(map, xs, zs.z, wx) + wz.w * wg_ocean_cubic_row(map, xs, zs.w, wx);
}

// A map pyramid at the world point xz at level of detail lod in [0, levels]: levels
// floor(lod) and the next, mixed by the fraction (trilinear, continuous across the levels:
// at an integer lod the two sides agree).
vec4 wg_ocean_map_lod(highp sampler2D map, vec2 xz, float texelsPerMetre, int n, int levels, float lod) {
  vec2 u = xz * texelsPerMetre;
  int l0 = min(int(floor(lod)), levels - 1);
  float f = lod - float(l0);
  return mix(wg_ocean_map_level(map, u, n, l0), wg_ocean_map_level(map, u, n, l0 + 1), f);
}

// The slope variance of one cascade that the shading loses at a footprint: its slopes'
// second moment there (moments.x + moments.y, the box means of dh/dx^2 + dh/dz^2) less what
// the normal keeps, the squared mean slope times the cascade's fade weight squared (a
// faded cascade hands all of its slopes to the roughness).
float wg_ocean_lost_variance(vec4 slopes, vec4 moments, float weight) {
  return moments.x + moments.y - weight * weight * (slopes.x * slopes.x + slopes.y * slopes.y);
}

// The perceptual roughness (ggx_specular's r, GGX alpha = r^2) widened by slope variance
// v: alpha'^2 = alpha^2 + v, v the sum of both axes' variances (a Beckmann lobe of alpha
// has slope variance alpha^2 / 2 per axis: LEAN mapping, Olano and Baker 2010, which
// Kaplanyan et al. 2016 and Tokuyoshi and Kaplanyan 2019 apply to GGX's alpha). r is held
// in [0, 1], v at 0 or more (rounding can leave a mean square a hair below the squared mean).
float wg_ocean_roughness(float r, float variance) {
  float rc = clamp(r, 0.0, 1.0);
  float a2 = rc * rc * rc * rc + max(variance, 0.0);
  return min(sqrt(sqrt(a2)), 1.0);
}
