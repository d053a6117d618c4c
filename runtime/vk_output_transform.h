#pragma once
// The Vulkan runtime's output transform pass (runtime/output_transform.h): what it binds
// and the pipeline that draws it. The frame (RGBA16F) is read through a combined image
// sampler at set 0, binding 0, texel for texel; 2^EV and the tone mapper are push
// constants; the display image (RGBA8 UNORM) receives the sRGB-encoded values.
#include "core/view_transform.h"
#include "runtime/vk_pipelines.h"
#include "runtime/vk_resources.h"
#include "runtime/vk_scene_spirv.h"

namespace wg::rt {

class VkOutputTransform {
 public:
  // `frame` is sampled (it must be in SHADER_READ_ONLY_OPTIMAL when the pass runs);
  // `displayFormat` is the format of the image the pass draws into.
  VkOutputTransform(VkContext& context, const VkSceneSpirv& spirv, const VkImageOwner& frame, VkFormat displayFormat);

  // Binds the pipeline, the frame and the view's constants and draws the full-screen
  // triangle, inside a rendering begun on the display image.
  void draw(VkCommandBuffer cmd, const ViewTransform& view) const;

 private:
  VkSamplerHandle sampler_;
  VkDescriptorSetLayoutHandle setLayout_;
  VkDescriptorPoolHandle pool_;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  VkPipelineLayoutHandle layout_;
  VkPipelineHandle pipeline_;
};

}  // namespace wg::rt
