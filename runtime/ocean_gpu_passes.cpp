// The spectral ocean's GPU passes' shared parts (runtime/ocean_gpu_passes.h).
#include "runtime/ocean_gpu_passes.h"

#include "runtime/runtime_error.h"

namespace wg::rt::oceangpu {

Texture floatTexture(int width, int height, GLenum format, int levels) {
  Texture t = makeTexture();
  glBindTexture(GL_TEXTURE_2D, t.id());
  glTexStorage2D(GL_TEXTURE_2D, levels, format, width, height);
  // Integer textures are complete only with nearest filtering; every pass uses texelFetch.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, levels > 1 ? GL_NEAREST_MIPMAP_NEAREST : GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return t;
}

Framebuffer targetOf(const Texture& first, const Texture* second, const char* what) {
  Framebuffer f = makeFramebuffer();
  glBindFramebuffer(GL_FRAMEBUFFER, f.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, first.id(), 0);
  if (second) glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, second->id(), 0);
  const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(second ? 2 : 1, buffers);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw RuntimeError(RuntimeError::Kind::Driver,
                       std::string("the GL driver cannot render into the ocean's float ") + what + " textures");
  return f;
}

Framebuffer targetOfLevel(const std::vector<const Texture*>& textures, int level, const char* what) {
  Framebuffer f = makeFramebuffer();
  glBindFramebuffer(GL_FRAMEBUFFER, f.id());
  std::vector<GLenum> buffers;
  for (size_t i = 0; i < textures.size(); ++i) {
    const GLenum attachment = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i);
    glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, textures[i]->id(), level);
    buffers.push_back(attachment);
  }
  glDrawBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw RuntimeError(RuntimeError::Kind::Driver,
                       std::string("the GL driver cannot render into the ocean's float ") + what + " textures");
  return f;
}

GLint location(const Program& p, const char* name) { return glGetUniformLocation(p.id(), name); }

void bindTexture(int unit, const Texture& t) {
  glActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D, t.id());
}

Program linkPass(SceneShaderApi api, const std::string& name, const std::string& fragment) {
  return linkProgram({{GL_VERTEX_SHADER, "fullscreen.vert", sceneShaderSources(api).fullscreenVertex},
                      {GL_FRAGMENT_SHADER, name + ".frag", fragment}},
                     "the ocean's " + name + " pass");
}

}  // namespace wg::rt::oceangpu
