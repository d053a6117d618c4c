#pragma once
// One cascade of the spectral ocean computed on the GPU by fragment passes into float
// textures (GL 4.5 core with glsl330 shaders, or ES 3.2 with es300 shaders): the evolution
// of h~(k, t) from the uploaded h0, 2 log2 N radix-2 Stockham passes of the inverse FFT,
// and a packing pass into two maps. The same computation in double is
// core/ocean_fft_reference.h; tests/runtime/ocean_gpu_cascade_test.cpp holds this to it
// within the float32 transform's error bound.
//
// Eight real fields ride in four complex transforms, two per RGBA32F texture: the inverse
// transform of a + i b, with a and b Hermitian spectra, is the real field of a plus i times
// that of b. Texture A holds (h + i Dx, Dz + i dh/dx), B holds (dh/dz + i dDx/dx, dDz/dz + i dDx/dz).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/ocean_fft_reference.h"
#include "runtime/gl_resources.h"
#include "runtime/scene.h"

namespace wg::rt {

class OceanGpuCascade {
 public:
  // Uploads h0 (rounded to float32) and the bins' frequency indices, and links the passes.
  // The GL context must be current; `api` is Gl330 or Es300. Without `slopes` (nothing
  // reads the slope map) only the first texture's two transforms run, half the work, and
  // the displacement map's w is 0.
  // With `jacobian` (the foam reads this cascade) it can also transform the Jacobian's
  // fields alone (jacobianFields). With `filtered` (a shader reads the moments map: the
  // filtered reader; implies slopes) the slope map and a moments map carry pyramids of
  // log2 N + 1 levels, each level the 2x2 box mean of the one above (the downsample pass).
  OceanGpuCascade(const ocean::OceanCascade& cascade, SceneShaderApi api, bool slopes = true, bool jacobian = false,
                  bool filtered = false);

  // Computes the maps at time t (seconds) with choppiness lambda. Leaves the viewport, the
  // draw framebuffer, the program, the vertex array and texture units 0-2 changed, and
  // depth testing and blending off.
  void update(double time, double choppiness);

  // The second texture's fields at time t alone (one texture's evolution and transform, half
  // of update's work with slopes): texel (jx, jz) holds (dh/dz, dDx/dx, dDz/dz, dDx/dz)
  // without the choppiness. The texture is the cascade's scratch: valid until the next
  // update or jacobianFields. Leaves the same state changed as update.
  const Texture& jacobianFields(double time);

  // The memory of a cascade's textures at resolution n: h0 and the frequencies, the two
  // spectra in ping and pong, the maps and the twiddles (half of the spectra and maps
  // without slopes).
  static size_t textureBytes(int n, bool slopes, bool filtered = false);

  int resolution() const { return n_; }
  bool computesSlopes() const { return slopes_; }
  bool filtered() const { return filtered_; }
  // The levels of the filtered pyramids: log2 N + 1 (1 unfiltered).
  int levels() const { return levels_; }
  // RGBA32F, N x N, texel (jx, jz) at x = jx L / N, z = jz L / N:
  //   displacement: (lambda Dx, h, lambda Dz, lambda dDx/dz)
  //   slopes:       (dh/dx, dh/dz, lambda dDx/dx, lambda dDz/dz)
  // so J = (1 + lambda dDx/dx)(1 + lambda dDz/dz) - (lambda dDx/dz)^2 of the summed cascades.
  GLuint displacementMap() const { return maps_[0].id(); }
  GLuint slopeMap() const { return maps_[1].id(); }  // 0 without slopes
  //   moments (filtered only): (dh/dx^2, dh/dz^2, dh/dx dh/dz, lambda dDx/dz)
  GLuint momentsMap() const { return moments_.id(); }  // 0 unfiltered
  // The two maps read back, N * N * 4 floats each, row jz * N + jx.
  std::vector<float> readDisplacement() const { return readMap(0); }
  std::vector<float> readSlopes() const { return readMap(1); }
  // Level `level` of the slope or moments pyramid read back, (N >> level)^2 * 4 floats.
  std::vector<float> readLevel(bool moments, int level) const;

 private:
  std::vector<float> readMap(int which) const;
  void drawInto(const Framebuffer& target) const;
  void beginPasses() const;
  void downsample() const;
  void evolve(const Program& program, double time, const Framebuffer& target) const;
  // The Stockham stages from spectra_[0] (both textures or the first alone) ping-ponging
  // through `targets`; returns the index of the spectra holding the result.
  int transform(const Program& stockham, bool both, const Framebuffer (&targets)[2]) const;

  int n_ = 0;
  bool slopes_ = true;
  bool jacobian_ = false;
  double tileLength_ = 0;
  Texture h0_, frequency_, twiddle_;
  Texture spectra_[2][2];  // [ping or pong][A or B]
  Framebuffer spectraTargets_[2];
  Texture maps_[2];
  Framebuffer mapTarget_;
  // Filtered: the moments map, and per level l >= 1 a target of level l of slopes and moments.
  bool filtered_ = false;
  int levels_ = 1;
  Texture moments_;
  std::vector<Framebuffer> levelTargets_;
  Program downsample_;
  VertexArray emptyVao_;
  Program evolve_, stockham_, pack_;
  // The Jacobian's fields alone, into spectra_[.][0] (with `jacobian`).
  Program evolveJacobian_, stockhamSingle_;
  Framebuffer jacobianTargets_[2];
};

}  // namespace wg::rt
