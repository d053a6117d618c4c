#pragma once
// What the Vulkan runtime's spectral ocean passes (runtime/vk_ocean_cascade.h,
// vk_ocean_foam.h) share: float images, and one pipeline per pass variant drawing a
// full-screen triangle into them from the GLSL text the GL runtime runs
// (runtime/ocean_gpu_shaders.h), compiled to SPIR-V by glslang as the scene's passes are
// (runtime/vk_scene_spirv.h). A pass is recorded into the frame's command buffer; its
// inputs' descriptor sets are made once per set of images and kept.
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "runtime/ocean_gpu_shaders.h"
#include "runtime/vk_pipelines.h"
#include "runtime/vk_resources.h"

namespace wg::rt {

// An N x N (or width x height) image of `format` that the ocean's passes sample, draw
// into, clear and read back.
VkImageOwner makeOceanImage(VkContext& context, int width, int height, VkFormat format, uint32_t levels = 1);

// The 32-bit word of a push constant (a float's bits, an int's two's complement, a uint).
uint32_t oceanConstantWord(float v);
inline uint32_t oceanConstantWord(int32_t v) { return static_cast<uint32_t>(v); }
inline uint32_t oceanConstantWord(uint32_t v) { return v; }

class VkOceanPass {
 public:
  // Throws std::logic_error when the runtime's own GLSL does not compile, RuntimeError
  // (Kind::Driver) when the driver refuses the pipeline.
  VkOceanPass(VkContext& context, oceangpu::OceanPass pass, const oceangpu::OceanPassVariant& variant);
  VkOceanPass(const VkOceanPass&) = delete;
  VkOceanPass& operator=(const VkOceanPass&) = delete;

  // Records the pass: `inputs` (one per sampler, binding order) moved to SHADER_READ_ONLY,
  // `outputs` (one per fragment output) to COLOR_ATTACHMENT and every texel written;
  // `constants` one word per push constant, in order.
  void record(VkCommandBuffer cmd, const std::vector<VkImageOwner*>& inputs, const std::vector<uint32_t>& constants,
              const std::vector<VkImageOwner*>& outputs);
  // Records the pass (no constants) reading the views `inputs` and drawing into the views
  // `outputs` (extent `extent`), all of images the caller holds in GENERAL layout: a pyramid
  // level drawn from the level above in the same images (different subresources).
  void recordLevels(VkCommandBuffer cmd, const std::vector<VkImageView>& inputs, const std::vector<VkImageView>& outputs,
                    VkExtent2D extent);

 private:
  VkDescriptorSet setFor(const std::vector<VkImageView>& views, VkImageLayout imageLayout);
  void draw(VkCommandBuffer cmd, VkDescriptorSet set, const std::vector<uint32_t>& constants,
            const std::vector<VkImageView>& outputs, VkImageLayout outputLayout, VkExtent2D extent);

  VkDevice device_;
  std::string name_;
  size_t samplers_ = 0, constants_ = 0, outputs_ = 0;
  VkSamplerHandle sampler_;
  VkDescriptorSetLayoutHandle setLayout_;
  VkPipelineLayoutHandle layout_;
  VkPipelineHandle pipeline_;
  std::vector<VkDescriptorPoolHandle> pools_;  // a new one when the last one's sets are spent
  std::map<std::pair<std::vector<VkImageView>, VkImageLayout>, VkDescriptorSet> sets_;
};

// The passes of one simulation, each variant made once and shared by its cascades. The
// images they read must live as long as they do (a descriptor set is kept per set of
// image views, and a later image could be given a destroyed one's handle).
class VkOceanPasses {
 public:
  explicit VkOceanPasses(VkContext& context) : context_(context) {}
  VkOceanPass& get(oceangpu::OceanPass pass, const oceangpu::OceanPassVariant& variant = {});
  VkContext& context() const { return context_; }

 private:
  VkContext& context_;
  std::map<std::pair<int, int>, std::unique_ptr<VkOceanPass>> passes_;  // (pass, variant bits)
};

}  // namespace wg::rt
