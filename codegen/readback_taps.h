#pragma once
// The tap mode of emission: the water's fragment stage rewritten by the planner, not by
// editing its text, so that `check` can read back what the GPU computed with (accuracy/
// readback.h). A tap frame runs main() as planned up to its colour statement and writes
// three floats main() holds there instead: the fragment depth, a varying (or deferred
// water's G-buffer local of the same name), a texture look-up main() made (re-made at the
// end of main(), where its coordinate is still in scope), or a texel of a scene texture at
// the pixel. Which ones is the caller's plan; every GLSL expression is made here.
#include <string>
#include <vector>

#include "codegen/emit_glsl.h"
#include "codegen/shader_plan.h"

namespace wg {

struct TapChannel {
  enum class Kind { Constant, FragDepth, Varying, Fetch, TexelAtPixel };
  Kind kind = Kind::Constant;
  double constant = 0;  // Constant
  // Varying: ShaderPlan::varyings; Fetch: the fragment stage's fetches; TexelAtPixel:
  // ShaderPlan::textures (a 2D sampler the fragment stage declares).
  size_t index = 0;
  int component = -1;  // -1: the value itself (a float, or a vector's x); else x, y, z or w
};

// What a drawn fragment stage's main() holds at its colour statement: forward water every
// varying and gl_FragCoord.z; deferred water, drawn over the screen, only the G-buffer
// locals its builtins need (codegen/plan_deferred.cpp), under the varyings' names.
bool tapHoldsFragDepth(const ShaderPlan& plan);
bool tapHoldsVarying(const ShaderPlan& plan, size_t varying);

// The fragment stage of `plan` (planShaders) as a tap frame for `target`: `channels` (three
// at most; 0.0 for the rest) as the colour's rgb, alpha 1.0. Throws std::logic_error for a
// plan whose fragment stage writes no colour or a channel it does not hold.
EmittedShader emitTapFragment(const ShaderPlan& plan, Target target, const std::vector<TapChannel>& channels);

// The same tap frame for the wgsl target (`check --target wgsl`): the WGSL module of `plan`
// (codegen/emit_wgsl.h, a plan without tessellation) with its fragment stage replaced by the
// tap frame's; vs_main is the graph's own. Throws WgslRefused as emitWgsl does.
std::string emitTapModuleWgsl(const ShaderPlan& plan, const std::vector<TapChannel>& channels);

}  // namespace wg
