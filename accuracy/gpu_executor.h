#pragma once
// Where `watergraph probe` and `check` run the generated shaders: one implementation per
// graphics API, so everything above it (cases, references, error bounds, sweeps, tap
// shaders) is written once for every target. GL (gl_executor.cpp): glsl330 on OpenGL 4.5
// core, es300 on OpenGL ES 3.2, through EGL, compiling the emitted GLSL text. Vulkan
// (vk_executor.cpp): vk450 on Vulkan 1.3 (lavapipe), running SPIR-V: for check the
// compile's own modules, the ones `compile --target vk450` writes; for the probe the probe
// shader's vk450 text through the same glslang path. WebGPU (wgsl_executor.cpp): the wgsl
// target's modules (the probe plan's; for check the compile's GRAPH.wgsl and its tap modules)
// in headless Chromium's WebGPU through Node.js.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "accuracy/probe_cases.h"
#include "codegen/compile.h"
#include "codegen/emit_glsl.h"
#include "codegen/readback_taps.h"
#include "runtime/renderer.h"

namespace wg::accuracy {

struct ExecutorOptions {
  // vk450: run under the Khronos validation layer; any message it reports is an error
  // (rt::RuntimeError, Kind::Driver). Refused for the GL targets.
  bool vulkanValidation = false;
  // vk450: ask the device for tessellation shaders, which a tessellated graph's water
  // needs (check); without it such a graph's frames are refused.
  bool tessellation = false;
};

// The water of one compiled graph drawn in the runtime's built-in scene, every pass of its
// plan, into an RGBA32F frame (RenderSettings::floatColor).
class WaterFrames {
 public:
  virtual ~WaterFrames() = default;
  virtual void setView(const rt::Camera& camera, const rt::SceneOptions& scene) = 0;
  // Renders one frame and reads it back, rows top to bottom.
  virtual rt::Image render() = 0;
  // Whether the frames sample the scene texture `s` with nearest filtering (else linear).
  virtual bool samplesNearest(SceneSampler s) const = 0;
};

// WaterFrames over a runtime renderer (rt::Renderer, rt::VkRenderer): both set a view and
// read a frame back the same way; only their construction differs.
template <class Renderer>
class RendererFrames : public WaterFrames {
 public:
  template <class... Args>
  explicit RendererFrames(Args&&... args) : renderer_(std::forward<Args>(args)...) {}
  void setView(const rt::Camera& camera, const rt::SceneOptions& scene) override {
    renderer_.setCamera(camera);
    renderer_.setScene(scene);
  }
  rt::Image render() override {
    renderer_.renderFrame();
    return renderer_.readRgba32f();
  }
  bool samplesNearest(SceneSampler s) const override { return renderer_.samplesNearest(s); }
  const Renderer& renderer() const { return renderer_; }

 private:
  Renderer renderer_;
};

class GpuExecutor {
 public:
  virtual ~GpuExecutor() = default;
  // The GLSL dialect it runs, or, for WGSL, the one whose plan its module shares (es300's:
  // no tessellation).
  virtual Target target() const = 0;
  // What the reports name: the target's name ("glsl330", "vk450", "wgsl").
  virtual std::string targetLabel() const { return std::string(targetName(target())); }
  virtual std::string deviceName() const = 0;  // GL_RENDERER, the Vulkan device's or the WebGPU adapter's name

  // The probe shader of `program` (codegen EmitMode::Probe) for this executor: the target's
  // GLSL, or the WGSL module (codegen/emit_wgsl.h emitWgslProbe). nullopt, with an error at
  // the node, when the program has no form for it.
  virtual std::optional<EmitResult> probeShader(const Program& program, const std::string& sourceName, Diagnostics& diags);

  // Runs a probe shader (EmitMode::Probe, this target) per case: one RGBA32F pixel each
  // (probe_gpu.h, vk_probe.h). `what` names the shader in errors.
  virtual std::vector<std::array<float, 4>> runProbe(const EmitResult& shader, const Program& program,
                                                     const std::vector<ProbeCase>& cases, const std::string& what) = 0;

  // The water shaders check renders of `result` (compiled for this target): the target's GLSL
  // (rt::waterShaderSources), or for WGSL the compile's module as one source (stage
  // GL_FRAGMENT_SHADER, both entry points in its text). A mutation (check --mutate) edits these.
  virtual std::vector<rt::ShaderSource> waterShaders(const CompileResult& result);
  // `water` with the fragment stage written as the read-back tap frame `frame` holding
  // `channels` (codegen/readback_taps.h), from `shaders`, the plan `water` was emitted from.
  virtual std::vector<rt::ShaderSource> tapFrameShaders(const std::vector<rt::ShaderSource>& water, const ShaderPlan& shaders,
                                                        const std::vector<TapChannel>& channels, int frame);

  // Frames of `result` (compiled for this target). `water` is the target's water shaders as
  // rt::waterShaderSources gives them; `edited` says they were changed (tap shaders, a
  // mutation): GL compiles the texts either way, Vulkan runs the compile's SPIR-V modules
  // unless they were edited, and then compiles the edited texts with glslang.
  virtual std::unique_ptr<WaterFrames> waterFrames(const CompileResult& result, const std::vector<rt::ShaderSource>& water,
                                                   bool edited, const rt::RenderSettings& settings) = 0;

  // Throws rt::RuntimeError (Kind::Driver) for what the API reported after the last run
  // raised its own errors: on vk450 with validation, a message while frames were destroyed.
  // Call it once the probe or check is over (destructors cannot throw).
  virtual void finish() {}
};

// Makes the context for `target` (EGL for glsl330 and es300, a Vulkan device for vk450)
// and the executor that owns it. Throws rt::RuntimeError (Kind::Environment) when the
// context cannot be made, (Kind::Manifest) for a target that does not run here (the
// SPIRV-Cross targets) or validation asked of a GL target.
std::unique_ptr<GpuExecutor> makeGpuExecutor(Target target, const ExecutorOptions& options = {});

// The two implementations, which makeGpuExecutor picks between.
std::unique_ptr<GpuExecutor> makeGlExecutor(Target target);
std::unique_ptr<GpuExecutor> makeVkExecutor(const ExecutorOptions& options);

// What the WebGPU executor runs: Node.js and the client folder holding executor_server.mjs and
// its npm packages (clients/webgpu), and the Chromium it starts.
struct WebgpuTools {
  std::string node;       // the node executable
  std::string clientDir;  // clients/webgpu (with node_modules)
  std::string chromium = "/usr/bin/chromium";
};

// The WebGPU executor: probes, and check's frames of a graph compiled for es300 with
// CompileOptions::wgsl (accuracy/wgsl_water_frames.h). Throws rt::RuntimeError
// (Kind::Environment) when the page cannot run WebGPU: Chromium missing or not starting, no
// adapter; the message says why the probe or check did not run.
std::unique_ptr<GpuExecutor> makeWgslExecutor(const WebgpuTools& tools);

// A GL executor on the GL context current on this thread (made by the caller), for
// glsl330 or es300.
std::unique_ptr<GpuExecutor> currentGlExecutor(Target target);

}  // namespace wg::accuracy
