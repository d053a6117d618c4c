#pragma once
// SPIR-V of the runtime's own passes (sky, opaque scene, full-screen triangle, water
// G-buffer) for the Vulkan runtime, compiled from the same GLSL bodies the GL runtime
// runs (scene.h, SceneShaderApi::Vulkan450).
//
// Why compiled by glslang at run time rather than at build time: the G-buffer fragment
// shader reads the graph's varyings at the locations the graph's vertex shader writes
// them, which only the manifest says; and one GLSL text per pass for both APIs keeps the
// two runtimes drawing the same scene. glslang is linked already (it validates every
// compile), and the four small programs take a few milliseconds.
#include "runtime/scene.h"
#include "runtime/vk_pipelines.h"

namespace wg::rt {

struct VkSceneSpirv {
  VkShaderCode skyVertex, skyFragment;
  VkShaderCode opaqueVertex, opaqueFragment;
  VkShaderCode fullscreenVertex, waterGbufferFragment;
  VkShaderCode outputTransformFragment;  // runtime/output_transform.h
};

// Throws std::logic_error with glslang's messages if a runtime shader does not compile:
// a bug of the runtime, not of a graph.
VkSceneSpirv compileSceneSpirv(const GbufferInputLocations& gbuffer);

}  // namespace wg::rt
