#pragma once
// Vulkan objects that are only created and destroyed (pipelines, layouts, samplers,
// descriptor pools) as move-only owners, and the one function that builds every graphics
// pipeline of the runtime from a small description. Pipelines use dynamic rendering
// (Vulkan 1.3): each names the formats of the target it draws into instead of a
// VkRenderPass, and the viewport and scissor are set when drawing.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "codegen/target.h"

namespace wg::rt {

template <typename T, void (*Destroy)(VkDevice, T, const VkAllocationCallbacks*)>
class VkHandle {
 public:
  VkHandle() = default;
  VkHandle(VkDevice device, T handle) : device_(device), handle_(handle) {}
  ~VkHandle() { reset(); }
  VkHandle(VkHandle&& o) noexcept
      : device_(std::exchange(o.device_, VK_NULL_HANDLE)), handle_(std::exchange(o.handle_, VK_NULL_HANDLE)) {}
  VkHandle& operator=(VkHandle&& o) noexcept {
    if (this != &o) {
      reset();
      device_ = std::exchange(o.device_, VK_NULL_HANDLE);
      handle_ = std::exchange(o.handle_, VK_NULL_HANDLE);
    }
    return *this;
  }
  VkHandle(const VkHandle&) = delete;
  VkHandle& operator=(const VkHandle&) = delete;
  T get() const { return handle_; }
  void reset() {
    if (handle_) Destroy(device_, handle_, nullptr);
    handle_ = VK_NULL_HANDLE;
  }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  T handle_ = VK_NULL_HANDLE;
};

using VkPipelineHandle = VkHandle<VkPipeline, vkDestroyPipeline>;
using VkPipelineLayoutHandle = VkHandle<VkPipelineLayout, vkDestroyPipelineLayout>;
using VkDescriptorSetLayoutHandle = VkHandle<VkDescriptorSetLayout, vkDestroyDescriptorSetLayout>;
using VkDescriptorPoolHandle = VkHandle<VkDescriptorPool, vkDestroyDescriptorPool>;
using VkSamplerHandle = VkHandle<VkSampler, vkDestroySampler>;

struct VkShaderCode {
  ShaderStage stage{};
  std::string name;  // shown in errors: "lake.vk450.vert.spv"
  std::vector<uint32_t> spirv;
};

VkShaderStageFlagBits vkShaderStage(ShaderStage stage);

struct VkPipelineDescription {
  std::vector<VkShaderCode> stages;
  // One interleaved vertex buffer at binding 0 (none when attributes is empty).
  uint32_t vertexStride = 0;
  std::vector<VkVertexInputAttributeDescription> attributes;
  bool patches = false;  // tessellated: patch lists of 3 vertices, else triangle lists
  bool points = false;   // point lists (a test's capture of single vertices), else as above
  bool depthTest = true;  // LEQUAL, as the GL runtime
  bool depthWrite = true;
  bool blend = false;  // colour by source alpha, alpha ONE / ONE_MINUS_SRC_ALPHA (the water)
  std::vector<VkFormat> colorFormats;
  VkFormat depthFormat = VK_FORMAT_UNDEFINED;
  VkPipelineLayout layout = VK_NULL_HANDLE;
};

// A descriptor pool holding exactly one set of `layout` (with room for `sizes`), and that
// set: what the water's bindings and the output transform each need. Throws RuntimeError
// naming `what` when the driver refuses.
VkDescriptorPoolHandle allocateSingleSet(VkDevice device, VkDescriptorSetLayout layout,
                                         const std::vector<VkDescriptorPoolSize>& sizes, VkDescriptorSet* set,
                                         const std::string& what);

// No culling, and counter-clockwise triangles in GL's sense are front faces: the runtime
// keeps GL's clip-space y (see docs/ecosystem.md, "Loading vk450 in your engine"), which
// Vulkan's framebuffer y-down turns into clockwise, so frontFace is CLOCKWISE.
// Throws RuntimeError(Kind::Driver) naming `what` when the driver refuses.
VkPipelineHandle createGraphicsPipeline(VkDevice device, const VkPipelineDescription& d, const std::string& what);

}  // namespace wg::rt
