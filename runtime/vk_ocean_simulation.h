#pragma once
// RenderPass::OceanSimulation on Vulkan: the manifest's spectral oceans as the GL runtime
// simulates them (runtime/ocean_simulation.h), each a set of cascades
// (runtime/vk_ocean_cascade.h) and, where a shader samples it, their foam
// (runtime/vk_ocean_foam.h), recorded into the frame's command buffer. Only the maps the
// shaders read are computed (slopes where a slope map is sampled, foam where ocean_foam
// is reached), a time the maps already hold records nothing, and the foam reaches a
// frame's time as FoamHistory says, as on GL.
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "codegen/shader_plan.h"
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
  void forgetHeldTime() { heldAt_.reset(); }
  void setFoamHistory(FoamHistory history) { foamHistory_ = history; }
  int lastFoamSteps() const;  // over every cascade; 0 when the last record found the maps at its time
  long updatesRecorded() const { return updatesRecorded_; }
  // The image of a manifest's ocean map (a manifest error when it names none).
  VkImageOwner& map(const OceanMapRef& ref);
  bool computesSlopes(int ocean, int cascade) const;
  bool computesFoam(int ocean, int cascade) const;
  // As OceanSimulation::identity: equal identities can share one simulation.
  static std::string identity(const std::vector<OceanInfo>& oceans, const std::vector<TextureInfo>& textures);
  const std::string& identity() const { return identity_; }

 private:
  struct Ocean {
    double choppiness = 0;
    std::vector<std::unique_ptr<VkOceanCascade>> cascades;
    std::vector<std::unique_ptr<VkOceanFoam>> foam;  // per cascade, null where no shader reads it
  };
  std::unique_ptr<VkOceanPasses> passes_;
  std::vector<Ocean> oceans_;
  std::string identity_;
  FoamHistory foamHistory_ = FoamHistory::Replay;
  std::optional<std::pair<double, FoamHistory>> heldAt_;
  bool lastRecordRan_ = false;
  long updatesRecorded_ = 0;
};

}  // namespace wg::rt
