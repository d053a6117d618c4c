#pragma once
// One cascade of the spectral ocean on Vulkan: the GL runtime's passes
// (runtime/ocean_gpu_cascade.h: evolution of h~(k, t) from h0, 2 log2 N radix-2 Stockham
// passes of the inverse FFT, packing into a displacement and a slope map) from the same
// GLSL (runtime/ocean_gpu_shaders.h), as fragment passes into RGBA32F images recorded into
// the frame's command buffer. tests/runtime/vk_ocean_cascade_test.cpp holds it to the
// double reference (core/ocean_fft_reference.h) within the float32 transform's bound.
#include <cstddef>
#include <vector>

#include "core/ocean_fft_reference.h"
#include "runtime/vk_ocean_passes.h"

namespace wg::rt {

class VkOceanCascade {
 public:
  // Uploads h0 (rounded to float32), the bins' frequency indices and the twiddles, and
  // makes the pass variants it records (shared through `passes`). `slopes` and `jacobian`
  // as OceanGpuCascade's.
  VkOceanCascade(VkOceanPasses& passes, const ocean::OceanCascade& cascade, bool slopes = true, bool jacobian = false,
                 bool filtered = false);

  // Records the maps at time t (seconds) with choppiness lambda; they end in
  // SHADER_READ_ONLY_OPTIMAL, for the water passes.
  void record(VkCommandBuffer cmd, double time, double choppiness);
  // Records the second texture's fields at time t alone (OceanGpuCascade::jacobianFields):
  // the returned image is the cascade's scratch, valid until the next record.
  VkImageOwner& recordJacobianFields(VkCommandBuffer cmd, double time);

  int resolution() const { return n_; }
  bool computesSlopes() const { return slopes_; }
  // As OceanGpuCascade's: the slope and moments pyramids of log2 N + 1 levels.
  bool filtered() const { return filtered_; }
  int levels() const { return levels_; }
  // RGBA32F, N x N, texel (jx, jz) at image row jz, as OceanGpuCascade's maps.
  VkImageOwner& displacementMap() { return maps_[0]; }
  VkImageOwner& slopeMap();  // a std::logic_error without slopes
  VkImageOwner& momentsMap();  // a std::logic_error unfiltered
  // The maps read back (after the command buffer ran), N * N * 4 floats, row jz * N + jx.
  std::vector<float> readDisplacement();
  std::vector<float> readSlopes();
  // Level `level` of the slope or moments pyramid, (N >> level)^2 * 4 floats.
  std::vector<float> readLevel(bool moments, int level);

 private:
  void evolve(VkCommandBuffer cmd, VkOceanPass& pass, double time, const std::vector<VkImageOwner*>& outputs);
  // The Stockham stages from spectra_[0] (both textures or the first alone); returns the
  // index of the spectra holding the result.
  int transform(VkCommandBuffer cmd, VkOceanPass& stockham, bool both);

  VkContext& context_;
  int n_ = 0;
  bool slopes_ = true;
  double tileLength_ = 0;
  VkImageOwner h0_, frequency_, twiddle_;
  VkImageOwner spectra_[2][2];  // [ping or pong][A or B]
  VkImageOwner maps_[2];
  bool filtered_ = false;
  int levels_ = 1;
  VkImageOwner moments_;
  VkOceanPass* downsample_ = nullptr;
  VkOceanPass *evolve_, *stockham_, *pack_;
  // With `jacobian`: the first texture's variants (the Jacobian's fields alone).
  VkOceanPass *evolveJacobian_ = nullptr, *stockhamSingle_ = nullptr;
};

}  // namespace wg::rt
