// A normal from a height texture by central differences (the deferred water article's wave normals).

// The red channel at uv as GL_LINEAR + GL_REPEAT define it, computed in float from the
// four texels (texelFetch): hardware filtering quantises the weights (8 bits of sub-texel
// position on llvmpipe and most GPUs), and central differences divide that error by 2e.
float wg_bilinear_red(sampler2D tex, vec2 uv) {
  vec2 size = vec2(textureSize(tex, 0));
  vec2 t = uv * size - 0.5;
  vec2 i = floor(t);
  vec2 f = t - i;
  ivec2 a = ivec2(mod(i, size));
  ivec2 b = ivec2(mod(i + 1.0, size));
  float h00 = texelFetch(tex, a, 0).x;
  float h10 = texelFetch(tex, ivec2(b.x, a.y), 0).x;
  float h01 = texelFetch(tex, ivec2(a.x, b.y), 0).x;
  float h11 = texelFetch(tex, b, 0).x;
  return mix(mix(h00, h10, f.x), mix(h01, h11, f.x), f.y);
}

// The height gradient d h / d(u, v) in texture units: central differences `e` apart
// (e floored at 1/1024, the closest a float32 coordinate in [0, 1) resolves reliably)
// around fract(uv) (the texture repeats, so huge coordinates lose nothing), red channel.
vec2 wg_normal_from_height_gradient(sampler2D tex, vec2 uv, float e) {
  float d = max(e, 0.0009765625);
  vec2 c = fract(uv);
  float hx = wg_bilinear_red(tex, c + vec2(d, 0.0)) - wg_bilinear_red(tex, c - vec2(d, 0.0));
  float hy = wg_bilinear_red(tex, c + vec2(0.0, d)) - wg_bilinear_red(tex, c - vec2(0.0, d));
  return vec2(hx, hy) * (0.5 / d);
}
