#pragma once
// RenderPass::OceanSimulation: the spectral oceans a manifest lists ("oceans"), each a set
// of GPU cascades (runtime/ocean_gpu_cascade.h) updated once per frame, whose maps are the
// manifest's ocean textures. The settings are the ocean_spectrum node's options, parsed
// with the node's own parser and checked as the compiler checks them.
#include <memory>
#include <vector>

#include "codegen/shader_plan.h"
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
  // samples. Leaves the viewport, the framebuffer, the program and texture units 0-2
  // changed.
  void update(double time);
  // How the foam reaches a frame's time (Replay unless set: a frame depends on its time alone).
  void setFoamHistory(FoamHistory history) { foamHistory_ = history; }
  // The foam steps the last update ran, over every cascade.
  int lastFoamSteps() const;
  // The GL texture of a manifest's ocean map (a manifest error when it names none).
  GLuint map(const OceanMapRef& ref) const;
  // The GPU memory the simulation of these oceans holds (every cascade's textures), without
  // a GL context: what `render --stats` reports beside the render targets.
  static size_t textureBytes(const std::vector<OceanInfo>& oceans, const std::vector<TextureInfo>& textures);
  // Whether cascade `cascade` of ocean `ocean` computes the slope fields, and its foam.
  bool computesSlopes(int ocean, int cascade) const;
  bool computesFoam(int ocean, int cascade) const;

 private:
  struct Ocean {
    double choppiness = 0;
    std::vector<std::unique_ptr<OceanGpuCascade>> cascades;
    std::vector<std::unique_ptr<OceanGpuFoam>> foam;  // per cascade, null where no shader reads it
  };
  std::vector<Ocean> oceans_;
  FoamHistory foamHistory_ = FoamHistory::Replay;
};

}  // namespace wg::rt
