#include "accuracy/gpu_executor.h"

#include "accuracy/readback.h"
#include "runtime/preview.h"
#include "runtime/runtime_error.h"

namespace wg::accuracy {

std::optional<EmitResult> GpuExecutor::probeShader(const Program& program, const std::string& sourceName, Diagnostics&) {
  return emitProgram(program, target(), sourceName, EmitMode::Probe);
}

std::vector<rt::ShaderSource> GpuExecutor::waterShaders(const CompileResult& result) {
  return rt::waterShaderSources(result, target());
}

std::vector<rt::ShaderSource> GpuExecutor::tapFrameShaders(const std::vector<rt::ShaderSource>& water, const ShaderPlan& shaders,
                                                           const std::vector<TapChannel>& channels, int frame) {
  return tapShaders(water, shaders, target(), channels, frame);
}

std::unique_ptr<GpuExecutor> makeGpuExecutor(Target target, const ExecutorOptions& options) {
  if (target == Target::Vk450) return makeVkExecutor(options);
  if (options.vulkanValidation)
    throw rt::RuntimeError(rt::RuntimeError::Kind::Manifest,
                           "Vulkan validation needs the vk450 target (the layer checks Vulkan calls), not " +
                               std::string(targetName(target)));
  return makeGlExecutor(target);
}

}  // namespace wg::accuracy
