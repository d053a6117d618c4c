#include "runtime/vk_preview.h"

#include <algorithm>
#include <cstring>

#include "runtime/runtime_error.h"
#include "runtime/vk_renderer.h"

namespace wg::rt {

std::vector<VkShaderCode> waterSpirv(const CompileResult& result) {
  const ManifestTarget* files = result.manifest.target(targetName(Target::Vk450));
  if (!files) throw RuntimeError(RuntimeError::Kind::Manifest, "the graph was not compiled for vk450");
  std::vector<VkShaderCode> out;
  for (const ManifestStageFile& f : files->files) {
    auto it = std::find_if(result.files.begin(), result.files.end(), [&](const OutputFile& o) { return o.name == f.spirv; });
    if (f.spirv.empty() || it == result.files.end() || it->contents.size() % 4 != 0)
      throw RuntimeError(RuntimeError::Kind::Manifest, "the manifest names SPIR-V '" + f.spirv + "' for " + f.file +
                                                           " but the compile produced no such module");
    VkShaderCode code{f.stage, f.spirv, std::vector<uint32_t>(it->contents.size() / 4)};
    std::memcpy(code.spirv.data(), it->contents.data(), it->contents.size());
    out.push_back(std::move(code));
  }
  return out;
}

Preview renderVulkanPreview(const CompileResult& result, const RenderSettings& settings, int frames, bool warmup,
                            bool validation) {
  std::vector<VkShaderCode> water = waterSpirv(result);
  VulkanOptions options;
  options.validation = validation;
  options.tessellation = std::any_of(water.begin(), water.end(), [](const VkShaderCode& c) {
    return c.stage == ShaderStage::TessControl || c.stage == ShaderStage::TessEvaluation;
  });
  auto context = VkContext::create(options);
  Preview p;
  p.renderer = context->deviceName();
  p.version = "Vulkan " + context->apiVersion();
  {
    VkRenderer renderer(*context, result.manifest, std::move(water), settings, textureOrigins(result));
    p.measure(renderer, settings, frames, warmup);
  }  // Vulkan objects go before the device
  context->throwOnValidationMessages("destroying the renderer");
  return p;
}

}  // namespace wg::rt
