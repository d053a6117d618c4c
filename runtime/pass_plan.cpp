#include "runtime/pass_plan.h"

#include <algorithm>
#include <cmath>

#include "runtime/runtime_error.h"

namespace wg::rt {
namespace {

[[noreturn]] void failManifest(const std::string& m) { throw RuntimeError(RuntimeError::Kind::Manifest, m); }

}  // namespace

int scaledSize(int frameSize, double scale) {
  return std::max(1, static_cast<int>(std::lround(static_cast<double>(frameSize) * scale)));
}

const char* passName(PassKind p) { return renderPassRow(p).name.data(); }  // a literal: NUL-terminated

std::optional<PassKind> parsePassName(const std::string& name) { return parseRenderPass(name); }

size_t bytesPerPixel(ColorFormat f) {
  switch (f) {
    case ColorFormat::None: return 0;
    case ColorFormat::Rgba8: return 4;
    case ColorFormat::Rgba16f: return 8;
    case ColorFormat::Rgba32f: return 16;
  }
  return 0;
}

size_t bytesPerPixel(DepthFormat f) { return f == DepthFormat::Depth32f ? 4 : 0; }

size_t TargetSpec::bytes() const {
  size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height) * (cube ? 6 : 1);
  return pixels * (bytesPerPixel(color) + bytesPerPixel(depth));
}

bool PassPlan::runs(PassKind p) const { return std::find(passes.begin(), passes.end(), p) != passes.end(); }

const TargetSpec* PassPlan::target(const std::string& name) const {
  for (const auto& t : targets)
    if (t.name == name) return &t;
  return nullptr;
}

const TargetSpec* PassPlan::picture() const {
  if (const TargetSpec* d = target(kDisplayTarget)) return d;
  return targets.front().color == ColorFormat::Rgba8 ? &targets.front() : nullptr;
}

bool sampledNearest(const TargetSpec& target, bool floatLinear) {
  return target.color == ColorFormat::None || target.producedBy == PassKind::DeferredWater ||
         (target.color == ColorFormat::Rgba32f && !floatLinear);
}

size_t PassPlan::totalBytes() const {
  size_t n = 0;
  for (const auto& t : targets) n += t.bytes();
  return n;
}

PassPlan planPasses(const Manifest& manifest, const PlanOptions& options) {
  if (options.width <= 0 || options.height <= 0 || options.environmentSize <= 0)
    failManifest("render size must be positive");
  if (!manifest.lists(PassKind::WaterSurface)) failManifest("the manifest's \"passes\" list lacks water_surface");
  PassPlan plan;
  const ColorFormat frameColor = options.floatColor ? ColorFormat::Rgba32f : options.pictureFormat;
  plan.targets.push_back({"frame", PassKind::WaterSurface, "", frameColor, DepthFormat::Depth32f, options.width,
                          options.height, false});
  for (const auto& pass : renderPassTable()) {
    if (pass.id == PassKind::OutputTransform) {
      if (options.floatColor || !options.outputTransform) continue;
      plan.passes.push_back(pass.id);
      plan.targets.push_back({kDisplayTarget, pass.id, "", ColorFormat::Rgba8, DepthFormat::None, options.width,
                              options.height, false});
      continue;
    }
    if (pass.id != PassKind::OpaqueScene && !manifest.lists(pass.id)) continue;
    plan.passes.push_back(pass.id);
    // The targets of the pass: the samplers of the resources it produces.
    for (const auto& sampler : sceneSamplerTable()) {
      if (sceneResourceRow(sampler.resource).pass != pass.id) continue;
      const ColorFormat color = sampler.color == TargetColor::None      ? ColorFormat::None
                                : sampler.color == TargetColor::Float32 ? ColorFormat::Rgba32f
                                                                        : frameColor;
      const bool cube = sampler.type == Type::SamplerCube;
      // A scaled pass (manifest "pass_scales") renders into targets that fraction of the
      // frame's size; the water samples them by screen position in [0, 1], so any size works.
      const double scale = manifest.scaleOf(pass.id);
      const int width = cube ? options.environmentSize : scaledSize(options.width, scale);
      const int height = cube ? options.environmentSize : scaledSize(options.height, scale);
      plan.targets.push_back({std::string(sampler.target), pass.id, std::string(sampler.glslName), color,
                              sampler.depth ? DepthFormat::Depth32f : DepthFormat::None, width, height, cube});
    }
  }
  return plan;
}

}  // namespace wg::rt
