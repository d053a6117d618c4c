#pragma once
// Buffers and images for the Vulkan runtime, each owning its memory and destroying both
// when it goes out of scope (before the VkContext). Plain Vulkan: every buffer lives in
// host-visible, coherent memory (written through a mapping: lavapipe's memory is all host
// memory, and the runtime waits for every frame), images in device-local memory, filled
// and read through a staging buffer. Layouts are tracked per image, so a barrier always
// names the layout the image is really in.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "runtime/vk_context.h"

namespace wg::rt {

class VkBufferOwner {
 public:
  VkBufferOwner() = default;
  VkBufferOwner(VkContext& context, size_t bytes, VkBufferUsageFlags usage);
  ~VkBufferOwner();
  VkBufferOwner(VkBufferOwner&& o) noexcept { *this = std::move(o); }
  VkBufferOwner& operator=(VkBufferOwner&& o) noexcept;
  VkBuffer buffer() const { return buffer_; }
  size_t size() const { return size_; }
  void* data() const { return mapped_; }
  void write(const void* bytes, size_t count, size_t offset = 0);

 private:
  void release();
  VkDevice device_ = VK_NULL_HANDLE;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  void* mapped_ = nullptr;
  size_t size_ = 0;
};

struct VkImageSpec {
  VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
  uint32_t width = 1, height = 1;
  uint32_t layers = 1;  // 6 for a cube map
  uint32_t mipLevels = 1;
  bool cube = false;
  VkImageUsageFlags usage = 0;
};

class VkImageOwner {
 public:
  VkImageOwner() = default;
  VkImageOwner(VkContext& context, const VkImageSpec& spec);
  ~VkImageOwner();
  VkImageOwner(VkImageOwner&& o) noexcept { *this = std::move(o); }
  VkImageOwner& operator=(VkImageOwner&& o) noexcept;
  explicit operator bool() const { return image_ != VK_NULL_HANDLE; }

  VkImage image() const { return image_; }
  const VkImageSpec& spec() const { return spec_; }
  VkImageView view() const { return view_; }                          // every layer (a cube view for a cube)
  VkImageView layerView(uint32_t layer) const { return layerViews_[layer]; }  // one layer, level 0: an attachment
  // Level `level` of layer 0 alone, of a mipmapped 2D attachment image: a pyramid level drawn
  // from the level above (the ocean's filtered maps).
  VkImageView levelView(uint32_t level) const { return levelViews_.at(level); }
  VkImageLayout layout() const { return layout_; }
  VkImageAspectFlags aspect() const;
  size_t bytes() const;  // level 0 of every layer, from the format

  // Records a barrier moving every level and layer to `layout`, waiting for all earlier
  // work (the runtime's frames are short chains of passes; a full barrier between them
  // costs nothing measurable on lavapipe and cannot be wrong).
  void transition(VkCommandBuffer cmd, VkImageLayout layout);

 private:
  void release();
  VkDevice device_ = VK_NULL_HANDLE;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  std::vector<VkImageView> layerViews_;
  std::vector<VkImageView> levelViews_;
  VkImageSpec spec_;
  VkImageLayout layout_ = VK_IMAGE_LAYOUT_UNDEFINED;
};

size_t formatBytes(VkFormat format);  // per texel: RGBA8 4, RGBA16F 8, RGBA32F 16, D32 4, R32F/R32UI 4, RG32F 8
bool isDepthFormat(VkFormat format);

// Uploads RGBA8 texels (rows as given) to level 0 of a 2D image and, when it has more
// levels, fills them by linear blits; leaves it in SHADER_READ_ONLY_OPTIMAL.
void uploadRgba8(VkContext& context, VkImageOwner& image, const unsigned char* rgba);
// Uploads level 0, layer 0 of a single-level image of any format formatBytes knows (rows
// as given, width * height texels); leaves it in SHADER_READ_ONLY_OPTIMAL.
void uploadTexels(VkContext& context, VkImageOwner& image, const void* texels);
// Copies level 0, layer 0 into host memory, rows in the image's order (row 0 first).
std::vector<unsigned char> readBack(VkContext& context, VkImageOwner& image, uint32_t level = 0);  // one level of layer 0

}  // namespace wg::rt
