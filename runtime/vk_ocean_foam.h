#pragma once
// One cascade's persistent foam on Vulkan: the GL runtime's model and steps
// (runtime/ocean_gpu_foam.h: R32F foam states stepped from the cascade's own Jacobian, f_n
// and f_(n+1) kept, the map the shaders read blended between them at the frame's time),
// from the same GLSL, recorded into the frame's command buffer. The same FoamHistory: a
// still frame replays its last K steps from no foam, an animation continues.
#include <cstdint>
#include <vector>

#include "core/ocean_foam.h"
#include "runtime/ocean_gpu_foam.h"
#include "runtime/vk_ocean_cascade.h"

namespace wg::rt {

class VkOceanFoam {
 public:
  VkOceanFoam(VkOceanPasses& passes, int resolution, const ocean::FoamSettings& settings);

  // Records the foam's steps to time t from `cascade` (made with `jacobian`) with
  // choppiness lambda and the map; the map ends in SHADER_READ_ONLY_OPTIMAL.
  void record(VkCommandBuffer cmd, double time, double choppiness, VkOceanCascade& cascade, FoamHistory history);

  VkImageOwner& map() { return output_; }
  // The map read back (after the command buffer ran), N * N floats, row jz * N + jx.
  std::vector<float> readMap();
  int lastSteps() const { return lastSteps_; }  // the steps the last record ran (K + 1 for a replay)

 private:
  void step(VkCommandBuffer cmd, std::int64_t m, double choppiness, VkOceanCascade& cascade);

  VkContext& context_;
  ocean::FoamSettings settings_;
  VkImageOwner states_[3];  // a ring: f_n in current_, f_(n+1) in next_, the third written next
  VkImageOwner output_;
  VkOceanPass &step_, &blend_;
  int current_ = 0, next_ = 1;
  bool valid_ = false;
  std::int64_t at_ = 0;  // n: the states hold f_n and f_(n+1)
  int lastSteps_ = 0;
};

}  // namespace wg::rt
