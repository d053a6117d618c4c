#pragma once
// Which passes a frame runs and which render targets exist, decided from the manifest's
// "passes" list alone (no GL here, so it is tested with hand-made manifests). A pass runs
// only when the manifest lists it; a render target is created only for a pass that runs.
//
//   manifest pass        target         contents                         bound as
//   depth_prepass        scene_depth    DEPTH_COMPONENT32F               u_scene_depth
//   scene_color_copy     scene_color    colour copy of the opaque scene  u_scene_color
//   planar_reflection    reflection     colour + depth, mirrored camera  u_reflection
//   refraction           refraction     colour + depth, clipped below    u_refraction
//   environment_cubemap  environment    cube map of the sky (6 faces)    u_environment
//   deferred_water       water_normal   RGBA32F: normal.xz, uv           u_water_normal_uv
//                        water_position RGBA32F + depth: position, depth  u_water_surface
//   water_surface        frame          colour + depth (always)          -
// With deferred_water, water_surface draws the graph's fragment shader full-screen (see
// docs/architecture.md, "Deferred water").
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace wg::rt {

enum class PassKind {
  EnvironmentCubemap,
  DepthPrepass,
  PlanarReflection,
  Refraction,
  OpaqueScene,  // sky + scene into the frame; always runs, not listed in manifests
  SceneColorCopy,
  DeferredWater,  // the water G-buffer; water_surface then runs full-screen
  WaterSurface,
};

const char* passName(PassKind p);  // the manifest's name ("opaque_scene" for OpaqueScene)
std::optional<PassKind> parsePassName(const std::string& name);

enum class ColorFormat { None, Rgba8, Rgba32f };
enum class DepthFormat { None, Depth32f };

struct TargetSpec {
  std::string name;           // "frame", "scene_depth", ...
  PassKind producedBy;
  std::string sampler;        // the uniform it is bound to ("" for the frame)
  ColorFormat color = ColorFormat::None;
  DepthFormat depth = DepthFormat::None;
  int width = 0, height = 0;
  bool cube = false;          // six square faces of width x width
  size_t bytes() const;       // GPU memory of its images
};

struct PlanOptions {
  int width = 1280, height = 720;
  bool floatColor = false;    // colour targets in RGBA32F (accuracy renders) or RGBA8
  int environmentSize = 128;  // cube map face size
};

struct PassPlan {
  std::vector<PassKind> passes;     // in execution order
  std::vector<TargetSpec> targets;  // in creation order; "frame" first
  bool runs(PassKind p) const;
  const TargetSpec* target(const std::string& name) const;
  size_t totalBytes() const;
};

size_t bytesPerPixel(ColorFormat f);
size_t bytesPerPixel(DepthFormat f);

// Throws RuntimeError(Kind::Manifest) for a missing or malformed "passes" list, an unknown
// pass, a list without water_surface, or a pass the runtime does not implement yet.
PassPlan planPasses(const nlohmann::json& manifest, const PlanOptions& options);

}  // namespace wg::rt
