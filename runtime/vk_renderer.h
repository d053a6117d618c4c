#pragma once
// Executes one compiled graph on Vulkan from its vk450 SPIR-V and manifest, in the same
// built-in scene, with the same pass plan, cameras and render targets as the GL runtime
// (renderer.h), headless: every pass draws into images, the frame is read back. The
// conventions it follows are the ones docs/ecosystem.md ("Loading vk450 in your engine")
// asks of an engine: GL's clip-space y with Vulkan's [0, 1] depth (the runtime multiplies
// its GL projection by a depth-range correction), images stored bottom row first as GL
// stores them, counter-clockwise front faces in GL's sense (VK_FRONT_FACE_CLOCKWISE).
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "codegen/manifest.h"
#include "runtime/pass_plan.h"
#include "runtime/renderer.h"
#include "runtime/vk_context.h"
#include "runtime/vk_pipelines.h"

namespace wg::rt {

class VkOceanSimulation;

// Vulkan's clip space takes z in [0, w] where GL's takes [-w, w]: z' = (z + w) / 2. Every
// projection the runtime hands a Vulkan shader is this times the GL one, so depth-buffer
// values equal GL's window depths and the graph's depth nodes read the same numbers.
glm::mat4 vulkanDepthRangeCorrection();

class VkRenderer {
 public:
  // `water`: the graph's SPIR-V modules in pipeline order (vertex, [tessellation], fragment).
  // `context` must outlive the renderer and have the tessellation feature when the water
  // is tessellated. Throws RuntimeError as Renderer does; with validation, also when the
  // layer reports anything while the renderer is built (Kind::Driver). With `oceans`
  // (another VkRenderer's oceanSimulation() on this context for a manifest of the same
  // oceans and ocean maps), the two share one simulation, as Renderer's `oceans`.
  VkRenderer(VkContext& context, const Manifest& manifest, std::vector<VkShaderCode> water, const RenderSettings& settings,
             const std::map<std::string, TextureOrigin>& origins = {}, std::shared_ptr<VkOceanSimulation> oceans = nullptr);
  ~VkRenderer();
  VkRenderer(const VkRenderer&) = delete;
  VkRenderer& operator=(const VkRenderer&) = delete;

  // Records every planned pass into one command buffer, submits it and waits. Returns the
  // CPU wall time in milliseconds around recording, submission and the wait. With
  // validation, throws RuntimeError(Kind::Driver) when the layer reported anything.
  double renderFrame();
  // For the next frames, as Renderer's: another camera, another time and sun.
  void setCamera(const Camera& camera);
  void setScene(const SceneOptions& scene);
  void setView(const ViewTransform& view);  // the output transform's, as Renderer::setView

  Image readRgba8() const;     // the displayed image, as Renderer::readRgba8
  Image readRgba32f() const;   // the linear frame, as Renderer::readRgba32f
  std::vector<float> readDepth() const;  // rows top to bottom, as Renderer::readDepth

  const PassPlan& plan() const;
  // The spectral oceans' simulation (null when the plan runs no ocean_simulation pass).
  std::shared_ptr<VkOceanSimulation> oceanSimulation() const;
  bool samplesNearest(SceneSampler s) const;  // as Renderer::samplesNearest
  int createdTargetCount() const;
  size_t createdTargetBytes() const;  // level 0 of every image, from the formats

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace wg::rt
