#include "runtime/node_texture.h"

#include <algorithm>

namespace wg::rt {
namespace {

GLint glWrap(TextureWrap w) {
  switch (w) {
    case TextureWrap::Repeat: return GL_REPEAT;
    case TextureWrap::Clamp: return GL_CLAMP_TO_EDGE;
    case TextureWrap::Mirror: return GL_MIRRORED_REPEAT;
  }
  return GL_REPEAT;
}

// The number of levels of a full chain: 1 + floor(log2(max(w, h))).
GLsizei glFullChainLevels(int width, int height) {
  GLsizei levels = 1;
  for (int side = std::max(width, height); side > 1; side /= 2) ++levels;
  return levels;
}

}  // namespace

Texture makeNodeTexture(int width, int height, const unsigned char* rgba, const SamplerState& sampler) {
  const bool mipmapped = sampler.filter == TextureFilter::Mipmapped;
  Texture t = makeTexture();
  glBindTexture(GL_TEXTURE_2D, t.id());
  glTexStorage2D(GL_TEXTURE_2D, mipmapped ? glFullChainLevels(width, height) : 1,
                 sampler.colorSpace == TextureColorSpace::Srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, width, height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  const GLint mag = sampler.filter == TextureFilter::Nearest ? GL_NEAREST : GL_LINEAR;
  const GLint min = mipmapped ? GL_LINEAR_MIPMAP_LINEAR : mag;
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, mag);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, glWrap(sampler.wrap));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, glWrap(sampler.wrap));
  if (mipmapped) glGenerateMipmap(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, 0);
  return t;
}

}  // namespace wg::rt
