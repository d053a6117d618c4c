#pragma once
// What the double reference of one drawn pixel needs from the GPU, read back: the water
// fragment shader's interpolated inputs (world position, normal, uv, gl_FragCoord.z and
// each value the vertex stage hands over, displacement included) and every scene texture
// look-up it makes (depth, scene colour, reflection, refraction, environment) as the
// passes rendered them and the shader fetched them, and its node texture look-ups (as
// llvmpipe filtered them: the reference's own filtering differs in the last bits, which
// steep formulas downstream, a GGX highlight, would amplify past any bound). All of it is
// planned from the ShaderPlan the water shaders were emitted from (codegen/compile.h
// waterPlan): its varyings, the look-ups its fragment stage makes (PlannedStage::fetches)
// and the samplers it hands to functions. A "tap" frame is the fragment stage emitted in
// the tap mode (codegen/readback_taps.h): three of the planned values as the colour in
// place of the graph's, into the RGBA32F frame, so each float comes back exactly. The
// vertex shader and every other pass are the graph's own, so the same fragments win the
// depth test as in the graph's frame.
#include <memory>
#include <string>
#include <vector>

#include "accuracy/probe.h"
#include "codegen/compile.h"
#include "codegen/readback_taps.h"
#include "core/interface_tables.h"
#include "core/node_spec.h"
#include "runtime/renderer.h"

namespace wg::accuracy {

struct ReadbackPlan {
  std::vector<TapChannel> channels;  // one float main() holds each
  // First channel of each quantity; -1 where the fragment shader does not read it.
  int mask = -1;  // holds kWaterMark wherever the water surface was drawn
  int fragDepth = -1, worldPosition = -1, normal = -1, uv = -1;
  std::vector<int> varyings;  // per Program::varyings entry
  struct Lookup {
    SceneSampler sampler;
    int channel = -1;
    int size = 0;  // 1 for depth, 3 for colours
  };
  std::vector<Lookup> lookups;  // in the order main() makes them
  // Node texture look-ups (vec4 each), in the order main() makes them: the reference takes
  // these values (codegen/cpu_backend.h TextureFetches) instead of sampling on the CPU.
  struct NodeFetch {
    std::string source;
    int channel = -1;
  };
  std::vector<NodeFetch> textureFetches;
  // Deferred water, whose fragment shader runs on every pixel: each 2D scene texture it
  // samples is read back whole (texelFetch at gl_FragCoord: scene targets must be the frame's
  // size, so checkGraph renders a graph with reduced "pass_scales" at full size), and the
  // reference samples that image wherever the shader does: an SSR march, a refracted
  // look-up (EvalEnvironment::sceneImages). The G-buffer needs no channel: its look-ups at
  // this pixel are the surface builtins read back above.
  struct Image {
    SceneSampler sampler;
    int channel = -1;
    int size = 0;  // 1 for depth, 3 for colours
  };
  std::vector<Image> images;
  int frames() const { return (static_cast<int>(channels.size()) + 2) / 3; }
};

// A value no scene colour takes: the mask channel's literal.
inline constexpr float kWaterMark = -3.0f;

// Plans the read-back of the water fragment stage of `shaders` (waterPlan of `result`).
// Returns why the per-pixel reference cannot be built from it ("" when it can): a scene
// texture handed to a function by forward-drawn water (many look-ups a pixel, where the
// reference has one value per texture and the water does not cover the screen to read the
// texture whole), or the G-buffer read other than at this pixel.
std::string planReadback(const CompileResult& result, const ShaderPlan& shaders, ReadbackPlan* plan);

// The channels tap frame `frame` writes: 3*frame .. 3*frame+2 of `plan` (GpuExecutor::tapFrameShaders
// writes the frame's shaders for its target).
std::vector<TapChannel> tapFrameChannels(const ReadbackPlan& plan, int frame);

// `water` (a GLSL target's shaders, rt::waterShaderSources) with the fragment stage emitted as
// the tap frame writing `channels`, or tap frame `frame` of `plan`.
std::vector<rt::ShaderSource> tapShaders(const std::vector<rt::ShaderSource>& water, const ShaderPlan& shaders, Target target,
                                         const std::vector<TapChannel>& channels, int frame);
std::vector<rt::ShaderSource> tapShaders(const std::vector<rt::ShaderSource>& water, const ShaderPlan& shaders, Target target,
                                         const ReadbackPlan& plan, int frame);

// One view's channels, per pixel (rows top to bottom).
struct ReadbackImage {
  int width = 0, height = 0, channels = 0;
  std::vector<float> values;  // [(py * width + px) * channels + c]
  float at(int px, int py, int c) const { return values[(static_cast<size_t>(py) * width + px) * channels + c]; }
  bool water(int px, int py, const ReadbackPlan& plan) const;  // false outside the frame
  // The scene texture of `image` as the reference samples it, rows bottom-up as GL's t.
  SceneImage sceneImage(const ReadbackPlan::Image& image, bool nearest) const;
};

class GpuExecutor;
class WaterFrames;

// The tap renderers of a graph: one per frame of the plan, reused over the views, on the
// executor's API (the tap shaders are variants of its target's water shaders, compiled as
// edited texts). `mutation`, the user's edit of the water shaders (check --mutate), is
// applied to the tap frames too, wherever its text occurs in them.
class ReadbackRenderer {
 public:
  ReadbackRenderer(GpuExecutor& executor, const CompileResult& result, const std::vector<rt::ShaderSource>& water,
                   const ShaderPlan& shaders, ReadbackPlan plan, const rt::RenderSettings& settings,
                   const ShaderMutation& mutation = {});
  ~ReadbackRenderer();
  ReadbackImage read(const rt::Camera& camera, const rt::SceneOptions& scene);
  const ReadbackPlan& plan() const { return plan_; }
  bool samplesNearest(SceneSampler s) const;  // as the frames filter the scene texture

 private:
  ReadbackPlan plan_;
  std::vector<std::unique_ptr<WaterFrames>> renderers_;
};


}  // namespace wg::accuracy
