#pragma once
// How a node texture is sampled: wrap mode, filter and colour space. One value travels
// from the node (EmitContext::texture) through the emitter (one sampler per distinct
// source and state), the manifest ("sampler", written only when it differs from the
// default), the GL runtime and the probe (texture parameters, internal format, mipmaps)
// and the three.js client (wrapS/wrapT, filters, colorSpace), and the CPU reference
// (nodes/texture_sampling.h) samples by the same value.
//
// The default is what every node texture was before the state existed and what the
// texture nodes other than texture_sample still ask for: GL_REPEAT, GL_LINEAR, no
// mipmaps, the bytes read as linear data. A manifest without "sampler" means it.
#include <optional>
#include <string_view>

namespace wg {

enum class TextureWrap { Repeat, Clamp, Mirror };                // GL_REPEAT, GL_CLAMP_TO_EDGE, GL_MIRRORED_REPEAT
enum class TextureFilter { Nearest, Linear, Mipmapped };         // mipmapped: GL_LINEAR_MIPMAP_LINEAR, mag GL_LINEAR
enum class TextureColorSpace { Linear, Srgb };                   // srgb: GL_SRGB8_ALPHA8, decoded per texel

struct SamplerState {
  TextureWrap wrap = TextureWrap::Repeat;
  TextureFilter filter = TextureFilter::Linear;
  TextureColorSpace colorSpace = TextureColorSpace::Linear;
  bool operator==(const SamplerState&) const = default;
  bool isDefault() const { return *this == SamplerState{}; }
};

// The names graph options, manifests and the three.js client use ("repeat", "clamp",
// "mirror"; "nearest", "linear", "mipmapped"; "linear", "srgb"), in enumerator order.
std::string_view wrapName(TextureWrap w);
std::string_view filterName(TextureFilter f);
std::string_view colorSpaceName(TextureColorSpace c);
std::optional<TextureWrap> parseWrap(std::string_view name);
std::optional<TextureFilter> parseFilter(std::string_view name);
std::optional<TextureColorSpace> parseColorSpace(std::string_view name);

// The screen-space derivatives of a texture coordinate, (du/dx, dv/dx) and (du/dy, dv/dy):
// what a fragment shader's implicit derivatives give texture() to choose a mip level.
struct UvGradient {
  double dudx = 0, dvdx = 0, dudy = 0, dvdy = 0;
};

}  // namespace wg
