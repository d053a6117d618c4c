// The Vulkan side of GpuExecutor (gpu_executor.h): one VkContext (with the validation
// layer when asked), probe shaders through runProbeOnVulkan, water frames through
// rt::VkRenderer from the compile's vk450 SPIR-V. With validation, anything the layer
// reports fails the probe run or the frame that caused it.
#include <algorithm>

#include "accuracy/gpu_executor.h"
#include "accuracy/vk_probe.h"
#include "codegen/glslang_validate.h"
#include "runtime/runtime_error.h"
#include "runtime/preview.h"
#include "runtime/vk_preview.h"
#include "runtime/vk_ocean_simulation.h"
#include "runtime/vk_renderer.h"

namespace wg::accuracy {
namespace {

ShaderStage stageOf(GLenum glStage) {
  for (ShaderStage s : {ShaderStage::Vertex, ShaderStage::TessControl, ShaderStage::TessEvaluation, ShaderStage::Fragment})
    if (rt::glShaderStage(s) == glStage) return s;
  throw std::logic_error("a water shader of an unknown stage");
}

// Edited vk450 texts (tap shaders, a mutation) to SPIR-V, as the compile makes its modules.
std::vector<rt::VkShaderCode> compileEdited(const std::vector<rt::ShaderSource>& water) {
  std::vector<ShaderSource> sources;
  for (const auto& s : water) sources.push_back({stageOf(s.stage), s.name, s.text});
  ValidationResult r = validateShaders(Target::Vk450, sources);
  if (!r.ok) {
    std::string text = "glslang rejects the edited vk450 water shaders:";
    for (const auto& e : r.errors) text += "\n  " + e.fileName + ":" + std::to_string(e.line) + ": " + e.text;
    throw rt::RuntimeError(rt::RuntimeError::Kind::Driver, text);
  }
  std::vector<rt::VkShaderCode> out;
  for (size_t i = 0; i < sources.size(); ++i) out.push_back({sources[i].stage, sources[i].fileName, std::move(r.spirv[i])});
  return out;
}

class VkExecutor : public GpuExecutor {
 public:
  explicit VkExecutor(const ExecutorOptions& options) : tessellation_(options.tessellation) {
    rt::VulkanOptions vo;
    vo.validation = options.vulkanValidation;
    vo.tessellation = options.tessellation;
    context_ = rt::VkContext::create(vo);
  }
  Target target() const override { return Target::Vk450; }
  void finish() override { context_->throwOnValidationMessages("destroying the frames"); }
  std::string deviceName() const override { return context_->deviceName(); }
  std::vector<std::array<float, 4>> runProbe(const EmitResult& shader, const Program& program,
                                             const std::vector<ProbeCase>& cases, const std::string& what) override {
    return runProbeOnVulkan(*context_, shader, program, cases, what);
  }
  std::unique_ptr<WaterFrames> waterFrames(const CompileResult& result, const std::vector<rt::ShaderSource>& water, bool edited,
                                           const rt::RenderSettings& settings) override {
    std::vector<rt::VkShaderCode> modules = edited ? compileEdited(water) : rt::waterSpirv(result);
    const bool tessellated = std::any_of(modules.begin(), modules.end(), [](const rt::VkShaderCode& c) {
      return c.stage == ShaderStage::TessControl || c.stage == ShaderStage::TessEvaluation;
    });
    if (tessellated && !tessellation_)
      throw rt::RuntimeError(rt::RuntimeError::Kind::Environment,
                             "the water is tessellated and this Vulkan executor was made without tessellation shaders");
    // Frames of the same oceans share one simulation, as on GL (gl_executor.cpp).
    std::shared_ptr<rt::VkOceanSimulation> oceans = oceans_.lock();
    if (oceans && oceans->identity() != rt::VkOceanSimulation::identity(result.manifest.oceans, result.manifest.textures))
      oceans.reset();
    auto frames = std::make_unique<RendererFrames<rt::VkRenderer>>(*context_, result.manifest, std::move(modules), settings,
                                                                   rt::textureOrigins(result), oceans);
    oceans_ = frames->renderer().oceanSimulation();
    return frames;
  }

 private:
  bool tessellation_;
  std::unique_ptr<rt::VkContext> context_;
  std::weak_ptr<rt::VkOceanSimulation> oceans_;  // the last frames' oceans, while any frames hold them
};

}  // namespace

std::unique_ptr<GpuExecutor> makeVkExecutor(const ExecutorOptions& options) { return std::make_unique<VkExecutor>(options); }

}  // namespace wg::accuracy
