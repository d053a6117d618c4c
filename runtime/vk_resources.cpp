#include "runtime/vk_resources.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "runtime/runtime_error.h"

namespace wg::rt {

size_t formatBytes(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_D32_SFLOAT:
    case VK_FORMAT_R32_SFLOAT:
    case VK_FORMAT_R32_UINT: return 4;
    case VK_FORMAT_R16G16B16A16_SFLOAT:
    case VK_FORMAT_R32G32_SFLOAT: return 8;
    case VK_FORMAT_R32G32B32A32_SFLOAT: return 16;
    default: return 0;
  }
}

bool isDepthFormat(VkFormat format) { return format == VK_FORMAT_D32_SFLOAT; }

VkBufferOwner::VkBufferOwner(VkContext& context, size_t bytes, VkBufferUsageFlags usage)
    : device_(context.device()), size_(bytes) {
  VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  bci.size = bytes;
  bci.usage = usage;
  bci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  checkVk(vkCreateBuffer(device_, &bci, nullptr, &buffer_), "creating a buffer");
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(device_, buffer_, &req);
  VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  mai.allocationSize = req.size;
  mai.memoryTypeIndex =
      context.memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  checkVk(vkAllocateMemory(device_, &mai, nullptr, &memory_), "allocating buffer memory");
  checkVk(vkBindBufferMemory(device_, buffer_, memory_, 0), "binding buffer memory");
  checkVk(vkMapMemory(device_, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_), "mapping buffer memory");
}

VkBufferOwner::~VkBufferOwner() { release(); }

void VkBufferOwner::release() {
  if (!device_) return;
  if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
  if (memory_) vkFreeMemory(device_, memory_, nullptr);  // unmaps
  device_ = VK_NULL_HANDLE;
}

VkBufferOwner& VkBufferOwner::operator=(VkBufferOwner&& o) noexcept {
  if (this != &o) {
    release();
    device_ = std::exchange(o.device_, VK_NULL_HANDLE);
    buffer_ = std::exchange(o.buffer_, VK_NULL_HANDLE);
    memory_ = std::exchange(o.memory_, VK_NULL_HANDLE);
    mapped_ = std::exchange(o.mapped_, nullptr);
    size_ = std::exchange(o.size_, 0);
  }
  return *this;
}

void VkBufferOwner::write(const void* bytes, size_t count, size_t offset) {
  if (offset + count > size_) throw std::logic_error("VkBufferOwner::write past the end of the buffer");
  std::memcpy(static_cast<char*>(mapped_) + offset, bytes, count);
}

VkImageOwner::VkImageOwner(VkContext& context, const VkImageSpec& spec) : device_(context.device()), spec_(spec) {
  VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  ici.flags = spec.cube ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0;
  ici.imageType = VK_IMAGE_TYPE_2D;
  ici.format = spec.format;
  ici.extent = {spec.width, spec.height, 1};
  ici.mipLevels = spec.mipLevels;
  ici.arrayLayers = spec.layers;
  ici.samples = VK_SAMPLE_COUNT_1_BIT;
  ici.tiling = VK_IMAGE_TILING_OPTIMAL;
  ici.usage = spec.usage;
  ici.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  checkVk(vkCreateImage(device_, &ici, nullptr, &image_), "creating an image");
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(device_, image_, &req);
  VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  mai.allocationSize = req.size;
  mai.memoryTypeIndex = context.memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  checkVk(vkAllocateMemory(device_, &mai, nullptr, &memory_), "allocating image memory");
  checkVk(vkBindImageMemory(device_, image_, memory_, 0), "binding image memory");
  auto makeView = [&](VkImageViewType type, uint32_t firstLayer, uint32_t layers, uint32_t levels, uint32_t firstLevel = 0) {
    VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vci.image = image_;
    vci.viewType = type;
    vci.format = spec.format;
    vci.subresourceRange = {aspect(), firstLevel, levels, firstLayer, layers};
    VkImageView v = VK_NULL_HANDLE;
    checkVk(vkCreateImageView(device_, &vci, nullptr, &v), "creating an image view");
    return v;
  };
  view_ = makeView(spec.cube ? VK_IMAGE_VIEW_TYPE_CUBE : VK_IMAGE_VIEW_TYPE_2D, 0, spec.layers, spec.mipLevels);
  if (spec.usage & (VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT))
    for (uint32_t l = 0; l < spec.layers; ++l) layerViews_.push_back(makeView(VK_IMAGE_VIEW_TYPE_2D, l, 1, 1));
  if (spec.mipLevels > 1 && !spec.cube && (spec.usage & VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT))
    for (uint32_t level = 0; level < spec.mipLevels; ++level)
      levelViews_.push_back(makeView(VK_IMAGE_VIEW_TYPE_2D, 0, 1, 1, level));
}

VkImageOwner::~VkImageOwner() { release(); }

void VkImageOwner::release() {
  if (!device_) return;
  for (VkImageView v : layerViews_) vkDestroyImageView(device_, v, nullptr);
  for (VkImageView v : levelViews_) vkDestroyImageView(device_, v, nullptr);
  if (view_) vkDestroyImageView(device_, view_, nullptr);
  if (image_) vkDestroyImage(device_, image_, nullptr);
  if (memory_) vkFreeMemory(device_, memory_, nullptr);
  device_ = VK_NULL_HANDLE;
}

VkImageOwner& VkImageOwner::operator=(VkImageOwner&& o) noexcept {
  if (this != &o) {
    release();
    device_ = std::exchange(o.device_, VK_NULL_HANDLE);
    image_ = std::exchange(o.image_, VK_NULL_HANDLE);
    memory_ = std::exchange(o.memory_, VK_NULL_HANDLE);
    view_ = std::exchange(o.view_, VK_NULL_HANDLE);
    layerViews_ = std::exchange(o.layerViews_, {});
    levelViews_ = std::exchange(o.levelViews_, {});
    spec_ = o.spec_;
    layout_ = std::exchange(o.layout_, VK_IMAGE_LAYOUT_UNDEFINED);
  }
  return *this;
}

VkImageAspectFlags VkImageOwner::aspect() const {
  return isDepthFormat(spec_.format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
}

size_t VkImageOwner::bytes() const {
  return static_cast<size_t>(spec_.width) * spec_.height * spec_.layers * formatBytes(spec_.format);
}

void VkImageOwner::transition(VkCommandBuffer cmd, VkImageLayout layout) {
  VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  b.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
  b.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
  b.oldLayout = layout_;
  b.newLayout = layout;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image_;
  b.subresourceRange = {aspect(), 0, spec_.mipLevels, 0, spec_.layers};
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 0, nullptr, 0, nullptr,
                       1, &b);
  layout_ = layout;
}

void uploadRgba8(VkContext& context, VkImageOwner& image, const unsigned char* rgba) {
  const VkImageSpec& s = image.spec();
  VkBufferOwner staging(context, static_cast<size_t>(s.width) * s.height * 4, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  staging.write(rgba, staging.size());
  context.submit([&](VkCommandBuffer cmd) {
    image.transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {s.width, s.height, 1};
    vkCmdCopyBufferToImage(cmd, staging.buffer(), image.image(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    // Each further level from the one above by a linear blit (what glGenerateMipmap does),
    // with every level in TRANSFER_DST until the last barrier.
    int32_t w = static_cast<int32_t>(s.width), h = static_cast<int32_t>(s.height);
    for (uint32_t level = 1; level < s.mipLevels; ++level) {
      VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
      b.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
      b.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
      b.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
      b.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
      b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
      b.image = image.image();
      b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 1, 0, 1};
      vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr, 1, &b);
      VkImageBlit blit{};
      blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 0, 1};
      blit.srcOffsets[1] = {w, h, 1};
      w = std::max(w / 2, 1), h = std::max(h / 2, 1);
      blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1};
      blit.dstOffsets[1] = {w, h, 1};
      vkCmdBlitImage(cmd, image.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image.image(),
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
      b.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
      b.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
      b.srcAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
      b.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
      vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr, 1, &b);
    }
    image.transition(cmd, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  });
}

void uploadTexels(VkContext& context, VkImageOwner& image, const void* texels) {
  const VkImageSpec& s = image.spec();
  VkBufferOwner staging(context, static_cast<size_t>(s.width) * s.height * formatBytes(s.format), VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  staging.write(texels, staging.size());
  context.submit([&](VkCommandBuffer cmd) {
    image.transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {s.width, s.height, 1};
    vkCmdCopyBufferToImage(cmd, staging.buffer(), image.image(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    image.transition(cmd, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  });
}

std::vector<unsigned char> readBack(VkContext& context, VkImageOwner& image, uint32_t level) {
  const VkImageSpec& s = image.spec();
  const uint32_t width = std::max(s.width >> level, 1u), height = std::max(s.height >> level, 1u);
  VkBufferOwner staging(context, static_cast<size_t>(width) * height * formatBytes(s.format), VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  context.submit([&](VkCommandBuffer cmd) {
    const VkImageLayout previous = image.layout();
    image.transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    VkBufferImageCopy region{};
    region.imageSubresource = {image.aspect(), level, 0, 1};
    region.imageExtent = {width, height, 1};
    vkCmdCopyImageToBuffer(cmd, image.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.buffer(), 1, &region);
    if (previous != VK_IMAGE_LAYOUT_UNDEFINED) image.transition(cmd, previous);
  });
  const auto* p = static_cast<const unsigned char*>(staging.data());
  return std::vector<unsigned char>(p, p + staging.size());
}

}  // namespace wg::rt
