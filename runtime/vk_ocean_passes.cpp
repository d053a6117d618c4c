// The Vulkan runtime's spectral ocean passes (runtime/vk_ocean_passes.h).
#include "runtime/vk_ocean_passes.h"

#include <algorithm>
#include <bit>
#include <stdexcept>

#include "codegen/glslang_validate.h"
#include "runtime/runtime_error.h"
#include "runtime/vk_shader_inputs.h"

namespace wg::rt {
namespace {

constexpr uint32_t kOceanSetsPerPool = 32;
constexpr VkFormat kOceanSpectrumFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr VkFormat kOceanFoamFormat = VK_FORMAT_R32_SFLOAT;

std::string oceanPassName(oceangpu::OceanPass pass, const oceangpu::OceanPassVariant& v) {
  static const char* const names[] = {"ocean_evolve",    "ocean_stockham",   "ocean_pack",
                                      "ocean_foam_step", "ocean_foam_blend", "ocean_downsample"};
  return std::string(names[static_cast<int>(pass)]) + (v.slopes ? "_slopes" : "") + (v.jacobianOnly ? "_jacobian" : "") +
         (v.moments ? "_moments" : "");
}

// The formats the pass's fragment outputs write (as the GL runtime's textures).
std::vector<VkFormat> oceanPassOutputs(oceangpu::OceanPass pass, const oceangpu::OceanPassVariant& v) {
  using oceangpu::OceanPass;
  if (pass == OceanPass::FoamStep || pass == OceanPass::FoamBlend) return {kOceanFoamFormat};
  if (pass == OceanPass::Downsample) return {kOceanSpectrumFormat, kOceanSpectrumFormat};  // slopes and moments
  if (pass == OceanPass::Pack && v.moments) return std::vector<VkFormat>(3, kOceanSpectrumFormat);
  const bool two = v.slopes && !(pass == OceanPass::Evolve && v.jacobianOnly);
  return std::vector<VkFormat>(two ? 2 : 1, kOceanSpectrumFormat);
}

}  // namespace

VkImageOwner makeOceanImage(VkContext& context, int width, int height, VkFormat format, uint32_t levels) {
  VkImageSpec spec;
  spec.mipLevels = levels;
  spec.format = format;
  spec.width = static_cast<uint32_t>(width);
  spec.height = static_cast<uint32_t>(height);
  spec.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  if (format != VK_FORMAT_R32_UINT && format != VK_FORMAT_R32G32_SFLOAT) spec.usage |= VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  return VkImageOwner(context, spec);
}

uint32_t oceanConstantWord(float v) { return std::bit_cast<uint32_t>(v); }

VkOceanPass::VkOceanPass(VkContext& context, oceangpu::OceanPass pass, const oceangpu::OceanPassVariant& variant)
    : device_(context.device()), name_(oceanPassName(pass, variant)) {
  samplers_ = oceangpu::oceanPassSamplers(pass, variant).size();
  constants_ = oceangpu::oceanPassConstants(pass).size();
  const std::vector<VkFormat> outputs = oceanPassOutputs(pass, variant);
  outputs_ = outputs.size();
  // wg::ShaderSource (glslang's input), not the GL runtime's rt::ShaderSource.
  const std::vector<wg::ShaderSource> sources = {
      {ShaderStage::Vertex, "runtime fullscreen.vert", sceneShaderSources(SceneShaderApi::Vulkan450).fullscreenVertex},
      {ShaderStage::Fragment, "runtime " + name_ + ".frag",
       oceangpu::oceanPassFragment(pass, SceneShaderApi::Vulkan450, variant)}};
  ValidationResult compiled = validateShaders(Target::Vk450, sources);
  if (!compiled.ok) {
    std::string text = "the Vulkan runtime's ocean shaders do not compile:";
    for (const auto& e : compiled.errors) text += "\n  " + e.fileName + ":" + std::to_string(e.line) + ": " + e.text;
    throw std::logic_error(text);
  }
  // texelFetch ignores the sampler's filter; nearest is the one integer images allow.
  sampler_ = makeVkSampler(device_, false, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false);
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  for (uint32_t i = 0; i < samplers_; ++i)
    bindings.push_back({i, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
  VkDescriptorSetLayoutCreateInfo lci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  lci.bindingCount = static_cast<uint32_t>(bindings.size());
  lci.pBindings = bindings.data();
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  checkVk(vkCreateDescriptorSetLayout(device_, &lci, nullptr, &setLayout), "creating an ocean pass's set layout");
  setLayout_ = VkDescriptorSetLayoutHandle(device_, setLayout);
  VkPushConstantRange range{VK_SHADER_STAGE_FRAGMENT_BIT, 0, static_cast<uint32_t>(constants_ * 4)};
  VkPipelineLayoutCreateInfo plci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  plci.setLayoutCount = 1;
  plci.pSetLayouts = &setLayout;
  plci.pushConstantRangeCount = constants_ ? 1 : 0;
  plci.pPushConstantRanges = &range;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  checkVk(vkCreatePipelineLayout(device_, &plci, nullptr, &layout), "creating an ocean pass's pipeline layout");
  layout_ = VkPipelineLayoutHandle(device_, layout);
  VkPipelineDescription d;
  d.stages = {{ShaderStage::Vertex, sources[0].fileName, std::move(compiled.spirv[0])},
              {ShaderStage::Fragment, sources[1].fileName, std::move(compiled.spirv[1])}};
  d.depthTest = false;
  d.depthWrite = false;
  d.colorFormats = outputs;
  d.layout = layout;
  pipeline_ = createGraphicsPipeline(device_, d, "the ocean's " + name_ + " pass");
}

VkDescriptorSet VkOceanPass::setFor(const std::vector<VkImageView>& views, VkImageLayout imageLayout) {
  auto it = sets_.find({views, imageLayout});
  if (it != sets_.end()) return it->second;
  // A new pool when the last one's sets are spent (counted, never asked past its size).
  if (sets_.size() % kOceanSetsPerPool == 0) {
    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                              static_cast<uint32_t>(std::max<size_t>(samplers_, 1)) * kOceanSetsPerPool};
    VkDescriptorPoolCreateInfo pci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pci.maxSets = kOceanSetsPerPool;
    pci.poolSizeCount = 1;
    pci.pPoolSizes = &size;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    checkVk(vkCreateDescriptorPool(device_, &pci, nullptr, &pool), "creating an ocean pass's descriptor pool");
    pools_.emplace_back(device_, pool);
  }
  VkDescriptorSet set = VK_NULL_HANDLE;
  VkDescriptorSetLayout layout = setLayout_.get();
  VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  ai.descriptorPool = pools_.back().get();
  ai.descriptorSetCount = 1;
  ai.pSetLayouts = &layout;
  checkVk(vkAllocateDescriptorSets(device_, &ai, &set), "allocating an ocean pass's descriptor set");
  std::vector<VkDescriptorImageInfo> images;
  for (VkImageView v : views) images.push_back({sampler_.get(), v, imageLayout});
  std::vector<VkWriteDescriptorSet> writes;
  for (size_t i = 0; i < images.size(); ++i) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set;
    w.dstBinding = static_cast<uint32_t>(i);
    w.descriptorCount = 1;
    w.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    w.pImageInfo = &images[i];
    writes.push_back(w);
  }
  vkUpdateDescriptorSets(device_, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
  return sets_.emplace(std::make_pair(views, imageLayout), set).first->second;
}

void VkOceanPass::record(VkCommandBuffer cmd, const std::vector<VkImageOwner*>& inputs, const std::vector<uint32_t>& constants,
                         const std::vector<VkImageOwner*>& outputs) {
  if (inputs.size() != samplers_ || constants.size() != constants_ || outputs.size() != outputs_ || outputs.empty())
    throw std::logic_error("the ocean's " + name_ + " pass recorded with the wrong number of images or constants");
  std::vector<VkImageView> views, targets;
  for (VkImageOwner* image : inputs) {
    image->transition(cmd, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    views.push_back(image->view());
  }
  for (VkImageOwner* image : outputs) {
    image->transition(cmd, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    targets.push_back(image->layerView(0));
  }
  draw(cmd, setFor(views, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL), constants, targets,
       VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, {outputs[0]->spec().width, outputs[0]->spec().height});
}

void VkOceanPass::recordLevels(VkCommandBuffer cmd, const std::vector<VkImageView>& inputs,
                               const std::vector<VkImageView>& outputs, VkExtent2D extent) {
  if (inputs.size() != samplers_ || constants_ != 0 || outputs.size() != outputs_)
    throw std::logic_error("the ocean's " + name_ + " pass recorded with the wrong number of images or constants");
  draw(cmd, setFor(inputs, VK_IMAGE_LAYOUT_GENERAL), {}, outputs, VK_IMAGE_LAYOUT_GENERAL, extent);
}

void VkOceanPass::draw(VkCommandBuffer cmd, VkDescriptorSet set, const std::vector<uint32_t>& constants,
                       const std::vector<VkImageView>& outputs, VkImageLayout outputLayout, VkExtent2D extent) {
  std::vector<VkRenderingAttachmentInfo> attachments;
  for (VkImageView view : outputs) {
    VkRenderingAttachmentInfo info{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    info.imageView = view;
    info.imageLayout = outputLayout;
    info.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;  // the triangle covers every texel
    info.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachments.push_back(info);
  }
  VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
  ri.renderArea = {{0, 0}, extent};
  ri.layerCount = 1;
  ri.colorAttachmentCount = static_cast<uint32_t>(attachments.size());
  ri.pColorAttachments = attachments.data();
  vkCmdBeginRendering(cmd, &ri);
  VkViewport viewport{0, 0, static_cast<float>(extent.width), static_cast<float>(extent.height), 0.0f, 1.0f};
  VkRect2D scissor{{0, 0}, extent};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.get());
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.get(), 0, 1, &set, 0, nullptr);
  if (!constants.empty())
    vkCmdPushConstants(cmd, layout_.get(), VK_SHADER_STAGE_FRAGMENT_BIT, 0, static_cast<uint32_t>(constants.size() * 4),
                       constants.data());
  vkCmdDraw(cmd, 3, 1, 0, 0);
  vkCmdEndRendering(cmd);
}

VkOceanPass& VkOceanPasses::get(oceangpu::OceanPass pass, const oceangpu::OceanPassVariant& variant) {
  const std::pair<int, int> key{static_cast<int>(pass),
                                (variant.slopes ? 1 : 0) + (variant.jacobianOnly ? 2 : 0) + (variant.moments ? 4 : 0)};
  auto it = passes_.find(key);
  if (it == passes_.end()) it = passes_.emplace(key, std::make_unique<VkOceanPass>(context_, pass, variant)).first;
  return *it->second;
}

}  // namespace wg::rt
