#include "runtime/vk_shader_inputs.h"

#include <algorithm>
#include <cstring>

#include "nodes/texture_source.h"
#include "runtime/runtime_error.h"

namespace wg::rt {
namespace {

VkSamplerAddressMode addressMode(TextureWrap w) {
  switch (w) {
    case TextureWrap::Repeat: return VK_SAMPLER_ADDRESS_MODE_REPEAT;
    case TextureWrap::Clamp: return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    case TextureWrap::Mirror: return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
  }
  return VK_SAMPLER_ADDRESS_MODE_REPEAT;
}

uint32_t vkFullChainLevels(int width, int height) {
  uint32_t levels = 1;
  for (int side = std::max(width, height); side > 1; side /= 2) ++levels;
  return levels;
}

}  // namespace

VkSamplerHandle makeVkSampler(VkDevice device, bool linear, VkSamplerAddressMode address, bool mipmapped) {
  VkSamplerCreateInfo sci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  sci.magFilter = sci.minFilter = linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  sci.mipmapMode = mipmapped ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
  sci.addressModeU = sci.addressModeV = sci.addressModeW = address;
  sci.maxLod = mipmapped ? VK_LOD_CLAMP_NONE : 0.0f;
  VkSampler s = VK_NULL_HANDLE;
  checkVk(vkCreateSampler(device, &sci, nullptr, &s), "creating a sampler");
  return VkSamplerHandle(device, s);
}

VkNodeTexture loadVkNodeTexture(VkContext& context, const TextureInfo& t, const std::string& graphDir,
                                const std::string& owner) {
  std::string why;
  auto img = loadTexture(t.source, graphDir, &why);
  if (!img || img->width <= 0 || img->height <= 0 ||
      img->rgba.size() != static_cast<size_t>(img->width) * static_cast<size_t>(img->height) * 4) {
    if (why.empty()) why = "no image data";
    throw TextureLoadError(owner + ": texture '" + t.source + "' cannot be loaded: " + why, t.source, why);
  }
  const bool mipmapped = t.sampler.filter == TextureFilter::Mipmapped;
  VkImageSpec spec;
  spec.format = t.sampler.colorSpace == TextureColorSpace::Srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
  spec.width = static_cast<uint32_t>(img->width);
  spec.height = static_cast<uint32_t>(img->height);
  spec.mipLevels = mipmapped ? vkFullChainLevels(img->width, img->height) : 1;
  spec.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  VkNodeTexture out{VkImageOwner(context, spec), {}};
  uploadRgba8(context, out.image, img->rgba.data());  // row 0 at v = 0, as GL
  out.sampler = makeVkSampler(context.device(), t.sampler.filter != TextureFilter::Nearest, addressMode(t.sampler.wrap), mipmapped);
  return out;
}

void writeBlockMember(unsigned char* block, const BlockMember& member, Type type, const std::vector<float>& v) {
  unsigned char* at = block + member.offset;
  switch (type) {
    case Type::Int:
    case Type::Bool: {
      int32_t i = static_cast<int32_t>(v[0]);
      std::memcpy(at, &i, 4);
      break;
    }
    case Type::Mat3:  // three columns, each padded to 16 bytes
      for (int c = 0; c < 3; ++c) std::memcpy(at + 16 * c, v.data() + 3 * c, 12);
      break;
    default: std::memcpy(at, v.data(), v.size() * sizeof(float)); break;
  }
}

}  // namespace wg::rt
