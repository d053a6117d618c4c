// The GL side of GpuExecutor (gpu_executor.h): probe shaders through runProbeOnGpu, water
// frames through rt::Renderer, on an EGL context it owns or the caller's current one.
#include <epoxy/gl.h>

#include "accuracy/gpu_executor.h"
#include "accuracy/probe_gpu.h"
#include "runtime/egl_context.h"
#include "runtime/ocean_simulation.h"
#include "runtime/preview.h"
#include "runtime/runtime_error.h"

namespace wg::accuracy {
namespace {

class GlExecutor : public GpuExecutor {
 public:
  GlExecutor(Target target, std::unique_ptr<rt::EglContext> context) : target_(target), context_(std::move(context)) {
    if (target != Target::Glsl330 && target != Target::Es300)
      throw rt::RuntimeError(rt::RuntimeError::Kind::Manifest,
                             std::string(targetName(target)) + " does not run on GL (glsl330 and es300 do)");
  }
  Target target() const override { return target_; }
  std::string deviceName() const override {
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return renderer ? renderer : "";
  }
  std::vector<std::array<float, 4>> runProbe(const EmitResult& shader, const Program& program,
                                             const std::vector<ProbeCase>& cases, const std::string& what) override {
    return runProbeOnGpu(shader, program, cases, target_ == Target::Es300, what);
  }
  std::unique_ptr<WaterFrames> waterFrames(const CompileResult& result, const std::vector<rt::ShaderSource>& water, bool,
                                           const rt::RenderSettings& settings) override {
    // Frames of the same oceans share one simulation (check's frames and its read-back
    // frames render each view at one time: the oceans run once for all of them).
    std::shared_ptr<rt::OceanSimulation> oceans = oceans_.lock();
    if (oceans && oceans->identity() != rt::OceanSimulation::identity(result.manifest.oceans, result.manifest.textures))
      oceans.reset();
    auto frames = std::make_unique<RendererFrames<rt::Renderer>>(result.manifest, water, settings, target_ == Target::Es300,
                                                                 rt::textureOrigins(result), nullptr, oceans);
    oceans_ = frames->renderer().oceanSimulation();
    return frames;
  }

 private:
  Target target_;
  std::unique_ptr<rt::EglContext> context_;  // null when the caller's context is current
  std::weak_ptr<rt::OceanSimulation> oceans_;  // the last frames' oceans, while any frames hold them
};

}  // namespace

std::unique_ptr<GpuExecutor> makeGlExecutor(Target target) {
  return std::make_unique<GlExecutor>(target, rt::EglContext::create(rt::apiFor(target)));
}

std::unique_ptr<GpuExecutor> currentGlExecutor(Target target) { return std::make_unique<GlExecutor>(target, nullptr); }

}  // namespace wg::accuracy
