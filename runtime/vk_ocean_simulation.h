#pragma once
// RenderPass::OceanSimulation on Vulkan: the manifest's spectral oceans as the GL runtime
// simulates them (runtime/ocean_simulation.h), each a set of cascades
// (runtime/vk_ocean_cascade.h) and, where a shader samples it, their foam
// (runtime/vk_ocean_foam.h), recorded into the frame's command buffer. Only the maps the
// shaders read are computed (slopes where a slope map is sampled, foam where ocean_foam
// is reached), a time the maps already hold records nothing, and the foam reaches a
// frame's time as FoamHistory says, as on GL.
#include <memory>
#include <string>
#include <vector>

#include "codegen/shader_plan.h"
#include "runtime/ocean_cascade_set.h"
#include "runtime/vk_ocean_foam.h"

namespace wg::rt {

class VkOceanSimulation {
 public:
  // Builds every ocean's cascades (initial amplitudes on the CPU, uploaded once) and the
  // pass pipelines. A manifest whose ocean options do not parse is a manifest error.
  VkOceanSimulation(VkContext& context, const std::vector<OceanInfo>& oceans, const std::vector<TextureInfo>& textures);

  // Records every cascade's maps at time t (seconds), and the foam of those whose foam a
  // shader samples; the maps end in SHADER_READ_ONLY_OPTIMAL. The command buffer must run
  // before the next record: the simulation counts the maps as holding time t from here.
  void record(VkCommandBuffer cmd, double time);
  // After a command buffer with a record failed: the maps hold no known time.
  void forgetHeldTime() { set_.forgetHeldTime(); }
  void setFoamHistory(FoamHistory history) { set_.setFoamHistory(history); }
  int lastFoamSteps() const { return set_.lastFoamSteps(); }  // 0 when the last record found the maps at its time
  long updatesRecorded() const { return set_.runs(); }
  // The image of a manifest's ocean map (a manifest error when it names none).
  VkImageOwner& map(const OceanMapRef& ref);
  bool computesSlopes(int ocean, int cascade) const { return set_.computesSlopes(ocean, cascade); }
  bool computesFoam(int ocean, int cascade) const { return set_.computesFoam(ocean, cascade); }
  // As OceanSimulation::identity: equal identities can share one simulation.
  static std::string identity(const std::vector<OceanInfo>& oceans, const std::vector<TextureInfo>& textures);
  const std::string& identity() const { return identity_; }

 private:
  std::unique_ptr<VkOceanPasses> passes_;  // before set_: its cascades hold the passes
  OceanCascadeSet<VkOceanCascade, VkOceanFoam> set_;
  std::string identity_;
};

}  // namespace wg::rt
