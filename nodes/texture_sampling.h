#pragma once
// GL's texture sampling rules in double precision: the CPU reference of every node that
// samples a node texture (EvalContext::sampleTexture). What it follows (OpenGL 4.6 core
// §8.14, the same rules as GL 3.3 and GLSL ES 3.00 in the form with integer texel
// coordinates):
//   - texel centres at (i + 0.5) / size; nearest reads texel floor(u size), linear blends
//     texels floor(u size - 0.5) and the next by the fraction of u size - 0.5;
//   - wrap on the integer texel index: repeat i mod size; clamp (GL_CLAMP_TO_EDGE)
//     clamp(i, 0, size - 1); mirror (GL_MIRRORED_REPEAT) (size - 1) - m(i mod 2 size - size)
//     with m(a) = a >= 0 ? a : -(1 + a);
//   - sRGB textures (GL_SRGB8_ALPHA8) decode each texel's r, g, b to linear BEFORE
//     filtering (alpha stays as stored), as GL requires;
//   - mipmapped is GL_LINEAR_MIPMAP_LINEAR with GL_LINEAR magnification: level of detail
//     lambda = log2(rho), rho = max(|du/dx| w, |dv/dx| h, |du/dy| w, |dv/dy| h) (the
//     approximation GL allows for the scale factor, and the one llvmpipe uses); lambda <= 0
//     is magnification (level 0, bilinear); above it levels floor(lambda) and the next are
//     each sampled bilinearly and blended by fract(lambda); from the last level on, the
//     last level alone.
// The mip chain is the one glGenerateMipmap builds, whose filter GL leaves to the
// implementation: Mesa (llvmpipe) blits each level from the previous one with a linear
// filter, i.e. level k+1 texel (i, j) is the bilinear, clamp-to-edge sample of level k at
// its centre (a 2x2 box filter where a side is even), computed in linear space (sRGB
// decoded, averaged, encoded again) and stored as 8-bit values, rounded to nearest.
#include <vector>

#include "core/sampler_state.h"
#include "core/value.h"
#include "nodes/texture_source.h"

namespace wg {

// A stored 8-bit component as the sampler returns it: byte / 255, or for sRGB r, g, b
// the sRGB transfer function decoded to linear.
double decodeTexel(std::uint8_t byte, TextureColorSpace space);
// Linear [0, 1] to the 8-bit value an sRGB (or, for Linear, UNORM) texture stores.
std::uint8_t encodeTexel(double linear, TextureColorSpace space);

// One level sampled with `filter` Nearest or Linear (Mipmapped reads as Linear here):
// vec4, r, g, b decoded per `space`. A non-finite coordinate reads at 0 rather than
// feeding NaN into an index.
Value sampleLevel(const TextureImage& level, double u, double v, TextureWrap wrap, TextureFilter filter,
                  TextureColorSpace space);

// Levels 1..q of `base` (q = floor(log2(max(w, h)))), as described above.
std::vector<TextureImage> buildMipChain(const TextureImage& base, TextureColorSpace space);

// The level of detail lambda of a look-up with `gradient` on `base` (-inf for a zero
// gradient).
double levelOfDetail(const TextureImage& base, const UvGradient& gradient);

// How far the value a GPU filters from an 8-bit texture may lie from sampleTexture's exact
// one: GL leaves the subtexel precision of filter weights to the implementation (Vulkan's
// minimum is 4 bits), and llvmpipe (lavapipe: subTexelPrecisionBits 8) blends 8-bit
// textures with 8-bit weights into an 8-bit result. With weights off by up to 2^-8 in
// each direction and the result rounded to 1/255: 2^-7 * spread + 2^-9, spread being the
// largest range of one component over the 2x2 level-0 footprint at (u, v). Zero for
// nearest filtering (stored values come back exactly). A minified mipmapped look-up blends
// coarser levels whose footprints this does not see: it is sized for level 0 only.
double filterUncertainty(const TextureImage& base, double u, double v, const SamplerState& sampler);

// The full rule: `chain` (levels 1..q of `base` for the state's colour space) is read
// only when the filter is Mipmapped and lambda > 0.
Value sampleTexture(const TextureImage& base, const std::vector<TextureImage>* chain, double u, double v,
                    const SamplerState& sampler, const UvGradient& gradient);

}  // namespace wg
