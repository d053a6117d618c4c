#include "codegen/readback_taps.h"

#include <stdexcept>

#include "codegen/emit_wgsl.h"
#include "codegen/shader_interface.h"
#include "core/number_format.h"

namespace wg {
namespace {

const PlannedStage& tapFragmentStage(const ShaderPlan& plan) {
  const PlannedStage* fs = plan.stage(ShaderStage::Fragment);
  if (!fs || fs->colorStatement == std::string::npos) throw std::logic_error("emitTapFragment: no colour statement in the plan");
  return *fs;
}

// Deferred water's G-buffer locals (deferredLocals): the surface texel serves world
// position, view direction and depth; the normal/uv texel the normal and uv.
bool holdsSurfaceLocal(const PlannedStage& fs) {
  return fs.builtins.count(Builtin::WorldPosition) || fs.builtins.count(Builtin::ViewDirection) ||
         fs.builtins.count(Builtin::FragDepth);
}

// The GLSL value of one channel, as a float.
std::string tapValue(const ShaderPlan& plan, const PlannedStage& fs, const TapChannel& c) {
  std::string e;
  switch (c.kind) {
    case TapChannel::Kind::Constant: return "float(" + formatGlslFloat(c.constant) + ")";
    case TapChannel::Kind::FragDepth:
      if (!tapHoldsFragDepth(plan)) throw std::logic_error("emitTapFragment: main() holds no fragment depth");
      e = plan.kind == ShaderPlan::Kind::Deferred ? "b_water_surface.w" : "gl_FragCoord.z";
      break;
    case TapChannel::Kind::Varying:
      if (!tapHoldsVarying(plan, c.index)) throw std::logic_error("emitTapFragment: main() does not hold that varying");
      e = plan.varyings.at(c.index).name;
      break;
    case TapChannel::Kind::Fetch: e = fs.fetches.at(c.index).call(); break;
    case TapChannel::Kind::TexelAtPixel: e = "texelFetch(" + plan.textures.at(c.index).name + ", ivec2(gl_FragCoord.xy), 0)"; break;
  }
  static const char* const kComponents[] = {".x", ".y", ".z", ".w"};
  // A look-up is a vec4 (a depth texture's too): its value is x, which GLSL's float() takes
  // and WGSL's f32() does not.
  const bool vec4 = c.kind == TapChannel::Kind::Fetch || c.kind == TapChannel::Kind::TexelAtPixel;
  const int component = c.component < 0 && vec4 ? 0 : c.component;
  if (component < 0) return "float(" + e + ")";
  if (component > 3) throw std::logic_error("emitTapFragment: a component past w");
  return "float((" + e + ")" + kComponents[component] + ")";
}

}  // namespace

bool tapHoldsFragDepth(const ShaderPlan& plan) {
  return plan.kind != ShaderPlan::Kind::Deferred || holdsSurfaceLocal(tapFragmentStage(plan));
}

bool tapHoldsVarying(const ShaderPlan& plan, size_t varying) {
  const VaryingInfo& v = plan.varyings.at(varying);
  if (plan.kind != ShaderPlan::Kind::Deferred) return true;
  const PlannedStage& fs = tapFragmentStage(plan);
  if (v.carries == "world_position") return holdsSurfaceLocal(fs);
  if (v.carries == "normal") return fs.builtins.count(Builtin::Normal) > 0;
  if (v.carries == "uv") return fs.builtins.count(Builtin::Uv) > 0;
  return false;  // a node's varying feeds the G-buffer pass only
}

namespace {

// The fragment stage of `plan` up to its colour statement, then the channels as the colour.
PlannedStage tapStage(const ShaderPlan& plan, const std::vector<TapChannel>& channels) {
  const PlannedStage& fs = tapFragmentStage(plan);
  if (channels.size() > 3) throw std::logic_error("emitTapFragment: more than three channels");
  std::string colour = "vec4(";
  for (size_t k = 0; k < 3; ++k) colour += (k < channels.size() ? tapValue(plan, fs, channels[k]) : "0.0") + ", ";
  colour += "1.0)";
  PlannedStage tap = fs;
  tap.body.keepFirst(fs.colorStatement);
  tap.body.assign(-1, 0, iface::kColorOutput, colour);
  return tap;
}

}  // namespace

EmittedShader emitTapFragment(const ShaderPlan& plan, Target target, const std::vector<TapChannel>& channels) {
  return emitStage(plan, tapStage(plan, channels), target);
}

std::string emitTapModuleWgsl(const ShaderPlan& plan, const std::vector<TapChannel>& channels) {
  ShaderPlan tapped = plan;
  for (PlannedStage& stage : tapped.stages)
    if (stage.stage == ShaderStage::Fragment) stage = tapStage(plan, channels);
  return emitWgsl(tapped).text;
}

}  // namespace wg
