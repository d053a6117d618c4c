#pragma once
// A node texture uploaded with its sampler state, so GL samples it as the CPU reference
// does (nodes/texture_sampling.h): the one place the runtime and the probe turn a
// SamplerState into GL texture state.
//   wrap      repeat | clamp | mirror   -> GL_REPEAT | GL_CLAMP_TO_EDGE | GL_MIRRORED_REPEAT (s and t)
//   filter    nearest                   -> min and mag GL_NEAREST, one level
//             linear                    -> min and mag GL_LINEAR, one level
//             mipmapped                 -> min GL_LINEAR_MIPMAP_LINEAR, mag GL_LINEAR, the full chain
//                                          from glGenerateMipmap
//   colour    linear | srgb             -> internal format GL_RGBA8 | GL_SRGB8_ALPHA8 (the sampler
//                                          decodes r, g, b per texel before filtering)
// The state lives in the texture object (no sampler objects): a PNG read with two states
// is two uploads, which the emitter's one-sampler-per-(source, state) rule makes explicit.
#include "core/sampler_state.h"
#include "runtime/gl_resources.h"

namespace wg::rt {

// `rgba` holds width * height * 4 bytes, row 0 (v = 0) first.
Texture makeNodeTexture(int width, int height, const unsigned char* rgba, const SamplerState& sampler);

}  // namespace wg::rt
