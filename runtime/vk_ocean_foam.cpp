// One cascade's persistent foam on Vulkan (runtime/vk_ocean_foam.h).
#include "runtime/vk_ocean_foam.h"

#include <cstring>

namespace wg::rt {

VkOceanFoam::VkOceanFoam(VkOceanPasses& passes, int resolution, const ocean::FoamSettings& settings)
    : context_(passes.context()),
      settings_(settings),
      step_(passes.get(oceangpu::OceanPass::FoamStep)),
      blend_(passes.get(oceangpu::OceanPass::FoamBlend)) {
  for (auto& s : states_) s = makeOceanImage(context_, resolution, resolution, VK_FORMAT_R32_SFLOAT);
  output_ = makeOceanImage(context_, resolution, resolution, VK_FORMAT_R32_SFLOAT);
  // The map starts readable: a water pass may bind it before the first update records.
  context_.submit([&](VkCommandBuffer cmd) { output_.transition(cmd, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL); });
}

void VkOceanFoam::step(VkCommandBuffer cmd, std::int64_t m, double choppiness, VkOceanCascade& cascade) {
  VkImageOwner& fields = cascade.recordJacobianFields(cmd, static_cast<double>(m) * settings_.step);
  const int written = 3 - current_ - next_;
  step_.record(cmd, {&fields, &states_[next_]},
               {oceanConstantWord(static_cast<float>(choppiness)), oceanConstantWord(static_cast<float>(ocean::foamKeep(settings_))),
                oceanConstantWord(static_cast<float>(ocean::foamGain(settings_))),
                oceanConstantWord(static_cast<float>(settings_.threshold))},
               {&states_[written]});
  current_ = next_;
  next_ = written;
  ++lastSteps_;
}

void VkOceanFoam::record(VkCommandBuffer cmd, double time, double choppiness, VkOceanCascade& cascade, FoamHistory history) {
  const std::int64_t n = ocean::stepIndex(settings_, time);
  const int k = ocean::historySteps(settings_);
  lastSteps_ = 0;
  const bool continues = valid_ && n >= at_ && (n == at_ || (history == FoamHistory::Continue && n - at_ <= k));
  if (continues) {
    for (std::int64_t m = at_ + 2; m <= n + 1; ++m) step(cmd, m, choppiness, cascade);
  } else {
    // f_(n-K) = 0 in next_, then K + 1 steps to f_(n+1).
    VkImageOwner& start = states_[next_];
    start.transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    const VkClearColorValue zero{};
    const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(cmd, start.image(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1, &all);
    for (std::int64_t m = n - k + 1; m <= n + 1; ++m) step(cmd, m, choppiness, cascade);
  }
  valid_ = true;
  at_ = n;
  blend_.record(cmd, {&states_[current_], &states_[next_]},
                {oceanConstantWord(static_cast<float>(ocean::foamFraction(settings_, time)))}, {&output_});
  output_.transition(cmd, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

std::vector<float> VkOceanFoam::readMap() {
  std::vector<unsigned char> bytes = readBack(context_, output_);
  std::vector<float> out(bytes.size() / sizeof(float));
  std::memcpy(out.data(), bytes.data(), out.size() * sizeof(float));
  return out;
}

}  // namespace wg::rt
