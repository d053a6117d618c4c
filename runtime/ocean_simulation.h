#pragma once
// RenderPass::OceanSimulation: the spectral oceans a manifest lists ("oceans"), each a set
// of GPU cascades (runtime/ocean_gpu_cascade.h) updated once per frame, whose maps are the
// manifest's ocean textures. The settings are the ocean_spectrum node's options, parsed
// with the node's own parser and checked as the compiler checks them.
#include <string>
#include <vector>

#include "codegen/shader_plan.h"
#include "runtime/ocean_cascade_set.h"
#include "runtime/ocean_gpu_cascade.h"
#include "runtime/ocean_gpu_foam.h"

namespace wg::rt {

class OceanSimulation {
 public:
  // Builds every ocean's cascades (initial amplitudes on the CPU, uploaded once). The GL
  // context must be current. A manifest whose ocean options do not parse is a manifest
  // error. `textures` are the shaders' (the manifest's): a cascade whose slope map none of
  // them samples computes its displacement alone (half the transforms).
  OceanSimulation(const std::vector<OceanInfo>& oceans, const std::vector<TextureInfo>& textures, SceneShaderApi api);

  // Every cascade's maps at time t (seconds), and the foam of those whose foam map a shader
  // samples. Leaves the viewport, the framebuffer, the program, the vertex array and
  // texture units 0-2 changed, and depth testing and blending off. After an update to the
  // same t with the same foam history the maps already hold time t: then nothing runs
  // (check renders many views of one time; a foam replay is tens of transforms per cascade).
  void update(double time);
  // How the foam reaches a frame's time (Replay unless set: a frame depends on its time alone).
  void setFoamHistory(FoamHistory history) { set_.setFoamHistory(history); }
  // The foam steps the last update ran, over every cascade (0 when it found the maps at its time).
  int lastFoamSteps() const { return set_.lastFoamSteps(); }
  // The updates that ran (not those that found the maps at their time).
  long updatesRun() const { return set_.runs(); }
  // The GL texture of a manifest's ocean map (a manifest error when it names none).
  GLuint map(const OceanMapRef& ref) const;
  // The GPU memory the simulation of these oceans holds (every cascade's textures), without
  // a GL context: what `render --stats` reports beside the render targets.
  static size_t textureBytes(const std::vector<OceanInfo>& oceans, const std::vector<TextureInfo>& textures);
  // Whether cascade `cascade` of ocean `ocean` computes the slope fields, and its foam.
  bool computesSlopes(int ocean, int cascade) const { return set_.computesSlopes(ocean, cascade); }
  bool computesFoam(int ocean, int cascade) const { return set_.computesFoam(ocean, cascade); }
  // What the simulation computes, as text: two manifests with equal identities (each
  // ocean's id and options, each ocean map a shader reads) can share one simulation.
  static std::string identity(const std::vector<OceanInfo>& oceans, const std::vector<TextureInfo>& textures);
  const std::string& identity() const { return identity_; }

 private:
  OceanCascadeSet<OceanGpuCascade, OceanGpuFoam> set_;
  std::string identity_;
};

}  // namespace wg::rt
