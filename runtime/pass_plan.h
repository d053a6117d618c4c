#pragma once
// Which passes a frame runs and which render targets exist, decided from the manifest's
// passes alone (no GL here, so it is tested with hand-made manifests). A pass runs
// only when the manifest lists it; a render target is created only for a pass that runs:
// "frame" (colour + depth, always), then one per scene sampler whose resource the pass
// produces (core/interface_tables.h: renderPassTable in execution order, sceneSamplerTable
// for each target's name, format and the sampler it is bound to), the frame's size or the
// fraction of it the manifest's "pass_scales" gives the pass. With deferred_water,
// water_surface draws the graph's fragment shader full-screen (see docs/architecture.md,
// "Deferred water").
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "codegen/manifest.h"
#include "core/interface_tables.h"

namespace wg::rt {

using PassKind = RenderPass;

const char* passName(PassKind p);  // the manifest's name ("opaque_scene" for OpaqueScene)
std::optional<PassKind> parsePassName(const std::string& name);

// Rgba16f: the frame and the scene targets of a picture render (linear, scene-referred
// radiance above 1 survives); Rgba32f: the same for accuracy renders (exact read-back);
// Rgba8: the displayed image the output transform writes (sRGB-encoded).
enum class ColorFormat { None, Rgba8, Rgba16f, Rgba32f };
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
  // Accuracy renders: colour targets in RGBA32F and no output transform (the linear frame is
  // read). Otherwise RGBA16F, and the output transform writes the "display" target (RGBA8).
  bool floatColor = false;
  // Only for measuring what the colour pipeline costs (bench/color_pipeline_bench.cpp): the
  // frame and scene targets of a picture render in RGBA8 (display values, as before the
  // pipeline) and/or without the output transform. Ignored with floatColor.
  ColorFormat pictureFormat = ColorFormat::Rgba16f;
  bool outputTransform = true;
  int environmentSize = 128;  // cube map face size
};

struct PassPlan {
  std::vector<PassKind> passes;     // in execution order
  std::vector<TargetSpec> targets;  // in creation order; "frame" first
  bool runs(PassKind p) const;
  const TargetSpec* target(const std::string& name) const;
  // The target holding the 8-bit picture: the display image the output transform writes,
  // or the frame itself when it is RGBA8 (measuring only); null for accuracy renders.
  const TargetSpec* picture() const;
  size_t totalBytes() const;
};

size_t bytesPerPixel(ColorFormat f);

// A frame dimension times a pass's scale (Manifest::scaleOf), rounded, at least 1.
int scaledSize(int frameSize, double scale);

// The 8-bit image the output transform writes; planned only without floatColor.
inline constexpr const char* kDisplayTarget = "display";

// Whether the renderers sample `target` with nearest filtering: depth and the water
// G-buffer are read texel for texel; colour is linear, except float colour on a device
// that cannot filter float textures (`floatLinear` false: OpenGL ES without
// GL_OES_texture_float_linear, a Vulkan device without the format feature).
bool sampledNearest(const TargetSpec& target, bool floatLinear);
size_t bytesPerPixel(DepthFormat f);

// Throws RuntimeError(Kind::Manifest) for passes without water_surface or a render size
// that is not positive. Duplicates count once; the opaque scene always runs.
PassPlan planPasses(const Manifest& manifest, const PlanOptions& options);

}  // namespace wg::rt
