#pragma once
// What a vk450 shader reads, made the same way wherever one runs: node textures loaded
// with their sampler state, samplers as GL's sampler state, and a value written at its
// std140 offset in the WgUniforms block. The renderer's water bindings
// (vk_water_bindings.h) and `watergraph probe` on vk450 (accuracy/vk_probe.h) both use
// these, so the probe checks the bytes the renderer writes.
#include <string>
#include <vector>

#include "codegen/shader_plan.h"
#include "codegen/uniform_block_layout.h"
#include "runtime/vk_pipelines.h"
#include "runtime/vk_resources.h"

namespace wg::rt {

// As GL's sampler state: min = mag filter, plus linear between levels when mipmapped.
VkSamplerHandle makeVkSampler(VkDevice device, bool linear, VkSamplerAddressMode address, bool mipmapped);

struct VkNodeTexture {
  VkImageOwner image;
  VkSamplerHandle sampler;
};
// The node texture `t` (builtin or a PNG under `graphDir`), uploaded with its colour space
// and mip chain, and its sampler. Throws TextureLoadError naming `owner` when it does not load.
VkNodeTexture loadVkNodeTexture(VkContext& context, const TextureInfo& t, const std::string& graphDir,
                                const std::string& owner);

// Writes `value` (a uniform's floats, column-major for matrices) into `block` at `member`,
// as std140 lays out a `type`: a mat3's columns padded to 16 bytes, int and bool as int32.
void writeBlockMember(unsigned char* block, const BlockMember& member, Type type, const std::vector<float>& value);

}  // namespace wg::rt
