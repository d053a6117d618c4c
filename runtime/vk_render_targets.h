#pragma once
// The render targets a pass plan lists (PassPlan::targets) as Vulkan images: colour and/or
// depth, sized as the plan says, sampled and copied by the passes (runtime/vk_renderer.h).
#include <cstddef>
#include <vector>

#include "runtime/pass_plan.h"
#include "runtime/vk_resources.h"

namespace wg::rt {

inline constexpr VkFormat kVkDepthFormat = VK_FORMAT_D32_SFLOAT;
VkFormat vkColorFormat(ColorFormat f);

struct VkTarget {
  TargetSpec spec;
  VkImageOwner color, depth;
};

class VkRenderTargets {
 public:
  // Makes every target of the plan, in its order (the frame first).
  void create(VkContext& context, const PassPlan& plan);

  VkTarget* find(SceneSampler s);
  VkTarget& frame() { return targets_.front(); }
  const VkTarget& frame() const { return targets_.front(); }
  // The target whose colour is the 8-bit picture (PassPlan::picture), or null.
  VkTarget* picture(const PassPlan& plan);
  // Whether RGBA32F images filter linearly on this device.
  bool floatLinear() const { return floatLinear_; }
  size_t size() const { return targets_.size(); }
  std::vector<VkTarget>::iterator begin() { return targets_.begin(); }
  std::vector<VkTarget>::iterator end() { return targets_.end(); }
  std::vector<VkTarget>::const_iterator begin() const { return targets_.begin(); }
  std::vector<VkTarget>::const_iterator end() const { return targets_.end(); }

 private:
  std::vector<VkTarget> targets_;
  bool floatLinear_ = true;
};

}  // namespace wg::rt
