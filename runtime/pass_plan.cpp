#include "runtime/pass_plan.h"

#include <algorithm>

#include "codegen/shader_interface.h"
#include "runtime/runtime_error.h"

namespace wg::rt {
namespace {

struct PassInfo {
  PassKind kind;
  const char* name;
};
// Execution order: everything the water samples first, then the frame itself.
constexpr PassInfo kPasses[] = {
    {PassKind::EnvironmentCubemap, "environment_cubemap"},
    {PassKind::DepthPrepass, "depth_prepass"},
    {PassKind::PlanarReflection, "planar_reflection"},
    {PassKind::Refraction, "refraction"},
    {PassKind::OpaqueScene, "opaque_scene"},
    {PassKind::SceneColorCopy, "scene_color_copy"},
    {PassKind::DeferredWater, "deferred_water"},
    {PassKind::WaterSurface, "water_surface"},
};

[[noreturn]] void fail(const std::string& m) { throw RuntimeError(RuntimeError::Kind::Manifest, m); }

}  // namespace

const char* passName(PassKind p) {
  for (const auto& i : kPasses)
    if (i.kind == p) return i.name;
  return "?";
}

std::optional<PassKind> parsePassName(const std::string& name) {
  for (const auto& i : kPasses)
    if (name == i.name) return i.kind;
  return std::nullopt;
}

size_t bytesPerPixel(ColorFormat f) {
  switch (f) {
    case ColorFormat::None: return 0;
    case ColorFormat::Rgba8: return 4;
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

size_t PassPlan::totalBytes() const {
  size_t n = 0;
  for (const auto& t : targets) n += t.bytes();
  return n;
}

PassPlan planPasses(const nlohmann::json& manifest, const PlanOptions& options) {
  if (options.width <= 0 || options.height <= 0 || options.environmentSize <= 0)
    fail("render size must be positive");
  auto it = manifest.find("passes");
  if (it == manifest.end() || !it->is_array()) fail("the manifest has no \"passes\" list");
  std::vector<bool> listed(std::size(kPasses), false);
  for (const auto& p : *it) {
    if (!p.is_string()) fail("the manifest's \"passes\" list holds a non-string entry");
    std::string name = p.get<std::string>();
    auto kind = parsePassName(name);
    if (!kind || *kind == PassKind::OpaqueScene) fail("the manifest lists an unknown pass '" + name + "'");
    for (size_t i = 0; i < std::size(kPasses); ++i)
      if (kPasses[i].kind == *kind) listed[i] = true;
  }
  PassPlan plan;
  ColorFormat color = options.floatColor ? ColorFormat::Rgba32f : ColorFormat::Rgba8;
  auto add2d = [&](const char* name, PassKind by, const char* sampler, ColorFormat c, DepthFormat d) {
    plan.targets.push_back({name, by, sampler, c, d, options.width, options.height, false});
  };
  bool water = false;
  for (size_t i = 0; i < std::size(kPasses); ++i) {
    if (kPasses[i].kind == PassKind::WaterSurface) water = listed[i];
  }
  if (!water) fail("the manifest's \"passes\" list lacks water_surface");
  add2d("frame", PassKind::WaterSurface, "", color, DepthFormat::Depth32f);
  for (size_t i = 0; i < std::size(kPasses); ++i) {
    PassKind k = kPasses[i].kind;
    if (k != PassKind::OpaqueScene && !listed[i]) continue;
    plan.passes.push_back(k);
    switch (k) {
      case PassKind::EnvironmentCubemap:
        plan.targets.push_back({"environment", k, iface::kEnvironmentTexture, color, DepthFormat::None, options.environmentSize,
                                options.environmentSize, true});
        break;
      case PassKind::DepthPrepass: add2d("scene_depth", k, iface::kSceneDepthTexture, ColorFormat::None, DepthFormat::Depth32f); break;
      case PassKind::PlanarReflection: add2d("reflection", k, iface::kReflectionTexture, color, DepthFormat::Depth32f); break;
      case PassKind::Refraction: add2d("refraction", k, iface::kRefractionTexture, color, DepthFormat::Depth32f); break;
      case PassKind::SceneColorCopy: add2d("scene_color", k, iface::kSceneColorTexture, color, DepthFormat::None); break;
      case PassKind::DeferredWater:
        // Positions need float precision whatever the frame's format; water_normal is
        // created first because water_position's framebuffer draws into both.
        add2d("water_normal", k, iface::kWaterNormalUvTexture, ColorFormat::Rgba32f, DepthFormat::None);
        add2d("water_position", k, iface::kWaterSurfaceTexture, ColorFormat::Rgba32f, DepthFormat::Depth32f);
        break;
      case PassKind::OpaqueScene:
      case PassKind::WaterSurface: break;
    }
  }
  return plan;
}

}  // namespace wg::rt
