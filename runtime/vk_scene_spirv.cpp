#include "runtime/vk_scene_spirv.h"

#include <stdexcept>

#include "codegen/glslang_validate.h"
#include "runtime/output_transform.h"

namespace wg::rt {
namespace {

// Compiles and links the shaders of one program; their SPIR-V in the same order.
std::vector<VkShaderCode> compileProgram(const std::vector<wg::ShaderSource>& sources) {
  ValidationResult r = validateShaders(Target::Vk450, sources);
  if (!r.ok) {
    std::string text = "the Vulkan runtime's own shaders do not compile:";
    for (const auto& e : r.errors) text += "\n  " + e.fileName + ":" + std::to_string(e.line) + ": " + e.text;
    throw std::logic_error(text);
  }
  std::vector<VkShaderCode> out;
  for (size_t i = 0; i < sources.size(); ++i) out.push_back({sources[i].stage, sources[i].fileName, std::move(r.spirv[i])});
  return out;
}

}  // namespace

VkSceneSpirv compileSceneSpirv(const GbufferInputLocations& gbuffer) {
  SceneShaderSources s = sceneShaderSources(SceneShaderApi::Vulkan450, gbuffer);
  VkSceneSpirv out;
  auto sky = compileProgram({{ShaderStage::Vertex, "runtime sky.vert", s.skyVertex},
                             {ShaderStage::Fragment, "runtime sky.frag", s.skyFragment}});
  out.skyVertex = std::move(sky[0]);
  out.skyFragment = std::move(sky[1]);
  auto opaque = compileProgram({{ShaderStage::Vertex, "runtime opaque.vert", s.opaqueVertex},
                                {ShaderStage::Fragment, "runtime opaque.frag", s.opaqueFragment}});
  out.opaqueVertex = std::move(opaque[0]);
  out.opaqueFragment = std::move(opaque[1]);
  out.fullscreenVertex = std::move(compileProgram({{ShaderStage::Vertex, "runtime fullscreen.vert", s.fullscreenVertex}})[0]);
  out.waterGbufferFragment =
      std::move(compileProgram({{ShaderStage::Fragment, "runtime water_gbuffer.frag", s.waterGbufferFragment}})[0]);
  out.outputTransformFragment = std::move(compileProgram({{ShaderStage::Fragment, "runtime output_transform.frag",
                                                          outputTransformFragment(SceneShaderApi::Vulkan450)}})[0]);
  return out;
}

}  // namespace wg::rt
