#pragma once
// What the graph's vk450 shaders read, bound as the manifest says: the std140 uniform
// block WgUniforms at set 0, binding 0 (member offsets from codegen/uniform_block_layout.h,
// rewritten every frame from the camera, time, sun and parameter values), and one combined
// image sampler per manifest texture at its binding: node textures (loaded here with their
// sampler state), scene textures (the render targets of the planned passes) and ocean maps
// (the ocean simulation's images, runtime/vk_ocean_simulation.h).
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "codegen/manifest.h"
#include "codegen/uniform_block_layout.h"
#include "runtime/renderer.h"
#include "runtime/uniform_values.h"
#include "runtime/vk_pipelines.h"
#include "runtime/vk_resources.h"
#include "runtime/vk_shader_inputs.h"

namespace wg::rt {

class VkWaterBindings {
 public:
  // `sceneImage` gives the image a scene sampler reads (null when no planned pass renders
  // it: a manifest error) and whether it is sampled with nearest filtering.
  struct SceneImage {
    VkImageOwner* image = nullptr;
    bool nearest = false;
  };
  // `oceanMap` gives the image of an ocean map (null when the manifest runs no ocean
  // simulation: a manifest error); ocean maps are sampled texel by texel (texelFetch).
  // Throws RuntimeError(Kind::Manifest) for uniforms or textures the runtime cannot provide,
  // TextureLoadError for a node texture that does not load.
  VkWaterBindings(VkContext& context, const Manifest& manifest, const std::function<SceneImage(SceneSampler)>& sceneImage,
                  const std::function<VkImageOwner*(const OceanMapRef&)>& oceanMap,
                  const std::map<std::string, TextureOrigin>& origins);

  VkDescriptorSetLayout setLayout() const { return setLayout_.get(); }
  // Writes the block for this frame.
  void writeUniforms(const FrameValues& frame);
  void bind(VkCommandBuffer cmd, VkPipelineLayout layout) const;
  // The scene images the water samples, to move into SHADER_READ_ONLY_OPTIMAL before a water pass.
  const std::vector<VkImageOwner*>& sampledSceneImages() const { return sceneImages_; }

 private:
  struct Uniform {
    std::string name;
    Type type = Type::Float;
    bool isParameter = false;
    BuiltinUniform builtin = BuiltinUniform::Time;
    double angularFrequency = 0;
    std::vector<float> value;  // a parameter's, clamped into its range
    BlockMember member;
  };
  std::vector<Uniform> uniforms_;
  size_t blockSize_ = 0;
  VkBufferOwner block_;
  std::vector<VkImageOwner> nodeTextures_;
  std::vector<VkSamplerHandle> samplers_;
  std::vector<VkImageOwner*> sceneImages_;
  VkDescriptorSetLayoutHandle setLayout_;
  VkDescriptorPoolHandle pool_;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
};

}  // namespace wg::rt
