#pragma once
// What the spectral ocean's GPU passes (runtime/ocean_gpu_cascade.h,
// runtime/ocean_gpu_foam.h) share: float textures read by texelFetch, the framebuffers
// drawing into them, and binding by unit.
#include <string>
#include <vector>

#include "runtime/gl_resources.h"
#include "runtime/scene.h"

namespace wg::rt::oceangpu {

// A width x height texture of `format` with nearest filtering (every pass uses texelFetch)
// and `levels` mip levels (a filtered cascade's pyramids; nearest-mipmap-nearest then, so
// that the texture is complete at every level texelFetch reads).
Texture floatTexture(int width, int height, GLenum format, int levels = 1);
// A framebuffer drawing into `first` and into `second` too when there is one; a driver
// that cannot render into them is a RuntimeError naming `what`.
Framebuffer targetOf(const Texture& first, const Texture* second, const char* what);
// A framebuffer drawing into level `level` of each of `textures` (attachments 0, 1, ...).
Framebuffer targetOfLevel(const std::vector<const Texture*>& textures, int level, const char* what);
GLint location(const Program& p, const char* name);
void bindTexture(int unit, const Texture& t);
// A full-screen pass's program: the scene's full-screen vertex shader and `fragment`
// (oceanPassFragment, runtime/ocean_gpu_shaders.h).
Program linkPass(SceneShaderApi api, const std::string& name, const std::string& fragment);

}  // namespace wg::rt::oceangpu
