#pragma once
// One call from a compiled graph to pixels on Vulkan, as renderPreview (preview.h) is for
// GL: makes the Vulkan device (with the validation layer when asked), builds the
// VkRenderer from the vk450 SPIR-V the compile produced and the manifest, renders
// `frames` frames and reads the last one back.
#include "codegen/compile.h"
#include "runtime/preview.h"
#include "runtime/vk_pipelines.h"

namespace wg::rt {

// The vk450 SPIR-V modules the manifest's "vk450" entry names, from the compile result.
// Throws RuntimeError(Kind::Manifest) when the graph was not compiled for vk450 or a
// module is missing.
std::vector<VkShaderCode> waterSpirv(const CompileResult& result);

// Throws RuntimeError; with `validation`, also when the layer is missing (Kind::Environment)
// or reports anything (Kind::Driver). Preview::renderer names the device, version its
// Vulkan version.
Preview renderVulkanPreview(const CompileResult& result, const RenderSettings& settings, int frames = 1, bool warmup = false,
                            bool validation = false);

}  // namespace wg::rt
