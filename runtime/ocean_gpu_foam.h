#pragma once
// One cascade's persistent foam on the GPU (core/ocean_foam.h holds the model and its
// double reference): R32F foam maps stepped by a fragment pass from the cascade's own
// Jacobian (OceanGpuCascade::jacobianFields), f_n and f_(n+1) kept, and the map the
// shaders read written between them at the frame's time.
#include <cstdint>
#include <vector>

#include "core/ocean_foam.h"
#include "runtime/gl_resources.h"
#include "runtime/ocean_gpu_cascade.h"
#include "runtime/scene.h"

namespace wg::rt {

// How a frame's foam is found: replayed from no foam over its last K steps (a still
// frame's foam depends on its time alone: render, check, probe), or continued from the
// previous frame's steps when it is at most K steps back (an animation: a frame costs the
// steps since the last, not K; it and the replay differ by at most e^(-K step / decay)).
enum class FoamHistory { Replay, Continue };

class OceanGpuFoam {
 public:
  // The GL context must be current; `cascade` must have been made with `jacobian`.
  OceanGpuFoam(int resolution, const ocean::FoamSettings& settings, SceneShaderApi api);

  // Steps the foam to time t from the cascade's Jacobian with choppiness lambda and writes
  // the map. Leaves the viewport, the framebuffer, the program, the vertex array and
  // texture units 0-2 changed, and depth testing and blending off.
  void update(double time, double choppiness, OceanGpuCascade& cascade, FoamHistory history);

  GLuint map() const { return output_.id(); }
  // The map read back, N * N floats, row jz * N + jx.
  std::vector<float> readMap() const;
  // The steps the last update ran (K + 1 for a replay).
  int lastSteps() const { return lastSteps_; }
  static size_t textureBytes(int n) { return static_cast<size_t>(n) * static_cast<size_t>(n) * 4 * 4; }

 private:
  void step(std::int64_t m, double choppiness, OceanGpuCascade& cascade);

  int n_ = 0;
  ocean::FoamSettings settings_;
  // A ring of three foam states: f_n in current_, f_(n+1) in next_, the third written next.
  Texture states_[3];
  Framebuffer stateTargets_[3];
  Texture output_;
  Framebuffer outputTarget_;
  VertexArray emptyVao_;
  Program step_, blend_;
  int current_ = 0, next_ = 1;
  bool valid_ = false;
  std::int64_t at_ = 0;  // n: the states hold f_n and f_(n+1)
  int lastSteps_ = 0;
};

}  // namespace wg::rt
