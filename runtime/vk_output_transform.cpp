#include "runtime/vk_output_transform.h"

#include "runtime/output_transform.h"
#include "runtime/runtime_error.h"
#include "runtime/vk_shader_inputs.h"

namespace wg::rt {
namespace {

// The fragment shader's push-constant block: float u_exposure_scale at 0, int u_tone_mapper at 4.
struct ViewConstants {
  float exposureScale;
  int32_t toneMapper;
};

}  // namespace

VkOutputTransform::VkOutputTransform(VkContext& context, const VkSceneSpirv& spirv, const VkImageOwner& frame,
                                     VkFormat displayFormat) {
  VkDevice device = context.device();
  sampler_ = makeVkSampler(device, /*linear=*/false, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, /*mipmapped=*/false);

  VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT,
                                       nullptr};
  VkDescriptorSetLayoutCreateInfo lci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  lci.bindingCount = 1;
  lci.pBindings = &binding;
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  checkVk(vkCreateDescriptorSetLayout(device, &lci, nullptr, &setLayout), "creating the output transform's set layout");
  setLayout_ = VkDescriptorSetLayoutHandle(device, setLayout);

  pool_ = allocateSingleSet(device, setLayout, {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}}, &set_,
                            "the output transform");
  VkDescriptorImageInfo image{sampler_.get(), frame.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  w.dstSet = set_;
  w.dstBinding = 0;
  w.descriptorCount = 1;
  w.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  w.pImageInfo = &image;
  vkUpdateDescriptorSets(device, 1, &w, 0, nullptr);

  VkPushConstantRange range{VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(ViewConstants)};
  VkPipelineLayoutCreateInfo plci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  plci.setLayoutCount = 1;
  plci.pSetLayouts = &setLayout;
  plci.pushConstantRangeCount = 1;
  plci.pPushConstantRanges = &range;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  checkVk(vkCreatePipelineLayout(device, &plci, nullptr, &layout), "creating the output transform's pipeline layout");
  layout_ = VkPipelineLayoutHandle(device, layout);

  VkPipelineDescription d;
  d.stages = {spirv.fullscreenVertex, spirv.outputTransformFragment};
  d.depthTest = false;
  d.depthWrite = false;
  d.colorFormats = {displayFormat};
  d.layout = layout;
  pipeline_ = createGraphicsPipeline(device, d, "the runtime's output transform");
}

void VkOutputTransform::draw(VkCommandBuffer cmd, const ViewTransform& view) const {
  const OutputTransformUniforms u = outputTransformUniforms(view);
  const ViewConstants c{u.exposureScale, u.toneMapper};
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.get());
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.get(), 0, 1, &set_, 0, nullptr);
  vkCmdPushConstants(cmd, layout_.get(), VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof c, &c);
  vkCmdDraw(cmd, 3, 1, 0, 0);
}

}  // namespace wg::rt
