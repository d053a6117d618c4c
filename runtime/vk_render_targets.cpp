// The render targets of a pass plan as Vulkan images (runtime/vk_render_targets.h).
#include "runtime/vk_render_targets.h"

namespace wg::rt {

VkFormat vkColorFormat(ColorFormat f) {
  switch (f) {
    case ColorFormat::Rgba32f: return VK_FORMAT_R32G32B32A32_SFLOAT;
    case ColorFormat::Rgba16f: return VK_FORMAT_R16G16B16A16_SFLOAT;
    default: return VK_FORMAT_R8G8B8A8_UNORM;
  }
}

void VkRenderTargets::create(VkContext& context, const PassPlan& plan) {
  VkFormatProperties floatProps;
  vkGetPhysicalDeviceFormatProperties(context.physicalDevice(), VK_FORMAT_R32G32B32A32_SFLOAT, &floatProps);
  floatLinear_ = floatProps.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
  for (const TargetSpec& spec : plan.targets) {
    VkTarget t;
    t.spec = spec;
    const auto transfer = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    if (spec.color != ColorFormat::None) {
      VkImageSpec s;
      s.format = vkColorFormat(spec.color);
      s.width = static_cast<uint32_t>(spec.width);
      s.height = static_cast<uint32_t>(spec.height);
      s.cube = spec.cube;
      s.layers = spec.cube ? 6 : 1;
      s.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | transfer;
      t.color = VkImageOwner(context, s);
    }
    if (spec.depth != DepthFormat::None) {
      VkImageSpec s;
      s.format = kVkDepthFormat;
      s.width = static_cast<uint32_t>(spec.width);
      s.height = static_cast<uint32_t>(spec.height);
      s.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | transfer;
      t.depth = VkImageOwner(context, s);
    }
    targets_.push_back(std::move(t));
  }
}

VkTarget* VkRenderTargets::find(SceneSampler s) {
  const std::string_view name = sceneSamplerRow(s).target;
  for (auto& t : targets_)
    if (t.spec.name == name) return &t;
  return nullptr;
}

VkTarget* VkRenderTargets::picture(const PassPlan& plan) {
  const TargetSpec* p = plan.picture();
  for (auto& t : targets_)
    if (p && t.spec.name == p->name) return &t;
  return nullptr;
}

}  // namespace wg::rt
