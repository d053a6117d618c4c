#pragma once
// Runs a probe shader (codegen EmitMode::Probe, target vk450) on Vulkan, as runProbeOnGpu
// (probe_gpu.h) runs it on GL: one pixel of an RGBA32F image per case, a full-screen
// triangle restricted to that pixel by the viewport. The fragment shader's vk450 text goes
// through glslang and spirv-val as `compile --target vk450` sends it (validateShaders), and
// the pipeline gets the manifest's interface: each case's uniforms written at their std140
// offsets (codegen/uniform_block_layout.h) in its own copy of the WgUniforms block (set 0,
// binding 0, bound at a dynamic offset per case), every sampler at its vk450 binding. Scene
// textures are 1x1 RGBA32F images (six layers for a cube) refilled with the case's texel
// before its draw; node textures are loaded as the Vulkan renderer loads them; ocean maps
// are the Vulkan runtime's simulation (runtime/vk_ocean_simulation.h), recorded before
// the first case of each time.
#include <array>
#include <string>
#include <vector>

#include "accuracy/probe_cases.h"
#include "codegen/emit_glsl.h"
#include "core/program.h"
#include "runtime/vk_context.h"

namespace wg::accuracy {

// Throws rt::RuntimeError (Driver: glslang or the driver rejects the shader, or the
// validation layer reported something; Manifest: a texture cannot be loaded).
std::vector<std::array<float, 4>> runProbeOnVulkan(rt::VkContext& context, const EmitResult& shader, const Program& program,
                                                   const std::vector<ProbeCase>& cases, const std::string& what);

}  // namespace wg::accuracy
