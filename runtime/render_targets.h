#pragma once
// The render targets a pass plan lists (PassPlan::targets), made on the current GL context:
// each a framebuffer with its colour and/or depth textures, sized and filtered as the plan
// says, and measured from the driver's view of the textures (render --stats); and a
// target's images read back.
#include <cstddef>
#include <vector>

#include "runtime/gl_resources.h"
#include "runtime/image.h"
#include "runtime/pass_plan.h"

namespace wg::rt {

// One render target: colour and/or depth textures and the framebuffer drawing into them.
struct GpuTarget {
  TargetSpec spec;
  Texture color;
  Texture depth;
  Framebuffer fbo;
  size_t allocatedBytes = 0;  // measured from the driver's view of the textures
};

class RenderTargets {
 public:
  // Makes every target of the plan, in its order (the frame first). `es`: an OpenGL ES
  // context, where float targets filter linearly only with OES_texture_float_linear. An
  // incomplete framebuffer is a RuntimeError (Driver).
  void create(const PassPlan& plan, bool es);

  GpuTarget* find(SceneSampler s);
  const GpuTarget& frame() const { return targets_.front(); }
  // The target whose colour is the 8-bit picture (PassPlan::picture), or null.
  const GpuTarget* picture(const PassPlan& plan) const;
  // Whether float targets are sampled with linear filtering on this context.
  bool floatLinear() const { return floatLinear_; }
  size_t size() const { return targets_.size(); }
  std::vector<GpuTarget>::const_iterator begin() const { return targets_.begin(); }
  std::vector<GpuTarget>::const_iterator end() const { return targets_.end(); }

 private:
  std::vector<GpuTarget> targets_;
  bool floatLinear_ = true;
};

// A target's colour read back, rows top to bottom: as floats (rgba32f) or bytes (rgba8).
Image readTargetColor(const GpuTarget& t, bool asFloat);
// A target's depth values read back, rows top to bottom (desktop GL: ES cannot).
std::vector<float> readTargetDepth(const GpuTarget& t);

}  // namespace wg::rt
