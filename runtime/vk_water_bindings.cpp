#include "runtime/vk_water_bindings.h"

#include <algorithm>
#include <cstring>
#include <limits>

#include "codegen/shader_interface.h"
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

// As GL's sampler state: min = mag filter, plus linear between levels when mipmapped.
VkSamplerHandle makeSampler(VkDevice device, bool linear, VkSamplerAddressMode address, bool mipmapped) {
  VkSamplerCreateInfo sci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  sci.magFilter = sci.minFilter = linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  sci.mipmapMode = mipmapped ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
  sci.addressModeU = sci.addressModeV = sci.addressModeW = address;
  sci.maxLod = mipmapped ? VK_LOD_CLAMP_NONE : 0.0f;
  VkSampler s = VK_NULL_HANDLE;
  checkVk(vkCreateSampler(device, &sci, nullptr, &s), "creating a sampler");
  return VkSamplerHandle(device, s);
}

uint32_t fullChainLevels(int width, int height) {
  uint32_t levels = 1;
  for (int side = std::max(width, height); side > 1; side /= 2) ++levels;
  return levels;
}

}  // namespace

VkWaterBindings::VkWaterBindings(VkContext& context, const Manifest& manifest,
                                 const std::function<SceneImage(SceneSampler)>& sceneImage,
                                 const std::map<std::string, TextureOrigin>& origins)
    : context_(context) {
  const VkDevice device = context.device();
  // The block: every non-sampler uniform in manifest order (= the shaders' declaration order).
  size_t end = 0;
  for (const ManifestUniform& m : manifest.uniforms) {
    if (isSampler(m.type)) manifestError("uniform " + m.name + " has a type the runtime cannot set: " + std::string(typeName(m.type)));
    Uniform u;
    u.name = m.name;
    u.type = m.type;
    u.member = std140Member(end, m.type);
    end = u.member.offset + u.member.size;
    if (m.parameter) {
      u.isParameter = true;
      u.value.assign(m.parameter->defaultValue.begin(), m.parameter->defaultValue.end());
      clampIntoRange(u.value, m.parameter->min ? static_cast<float>(*m.parameter->min) : -std::numeric_limits<float>::infinity(),
                     m.parameter->max ? static_cast<float>(*m.parameter->max) : std::numeric_limits<float>::infinity());
    } else {
      u.builtin = m.builtin;
      u.angularFrequency = m.angularFrequency;
      if (builtinUniformValue(u.builtin, u.angularFrequency, FrameValues{}).empty())
        manifestError("uniform " + u.name + " asks for builtin '" + std::string(builtinUniformRow(u.builtin).meaning) +
                      "', which the runtime does not provide");
    }
    if (u.isParameter && u.value.size() != static_cast<size_t>(componentCount(u.type)))
      manifestError("uniform " + u.name + " of type " + std::string(typeName(u.type)) + " got " + std::to_string(u.value.size()) +
                    " value(s)");
    uniforms_.push_back(std::move(u));
  }
  blockSize_ = (end + 15) / 16 * 16;

  std::vector<VkDescriptorSetLayoutBinding> bindings;
  if (blockSize_ > 0) {
    block_ = VkBufferOwner(context, blockSize_, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    bindings.push_back({static_cast<uint32_t>(iface::kUniformBlockBinding), VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
                        VK_SHADER_STAGE_ALL_GRAPHICS, nullptr});
  }
  // Textures: each at its manifest binding with the image and sampler it reads.
  std::vector<VkDescriptorImageInfo> images;
  for (const TextureInfo& t : manifest.textures) {
    const bool cube = t.type == Type::SamplerCube;
    VkDescriptorImageInfo info{};
    info.imageLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    if (t.scene) {
      SceneImage s = sceneImage(*t.scene);
      if (!s.image)
        manifestError("texture " + t.name + " (scene resource '" +
                      std::string(sceneResourceRow(sceneSamplerRow(*t.scene).resource).name) +
                      "') is not rendered by any pass the manifest lists");
      if (cube != s.image->spec().cube) manifestError("texture " + t.name + " has the wrong sampler type " + std::string(typeName(t.type)));
      samplers_.push_back(makeSampler(device, !s.nearest, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false));
      info.imageView = s.image->view();
      if (std::find(sceneImages_.begin(), sceneImages_.end(), s.image) == sceneImages_.end()) sceneImages_.push_back(s.image);
    } else {
      if (t.type != Type::Sampler2D) manifestError("node texture " + t.name + " must be a sampler2D, not " + std::string(typeName(t.type)));
      auto o = origins.find(t.source);
      std::string dir = o != origins.end() ? o->second.graphDir : ".";
      std::string owner = o != origins.end() ? o->second.owner : "texture " + t.name;
      std::string why;
      auto img = loadTexture(t.source, dir, &why);
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
      spec.mipLevels = mipmapped ? fullChainLevels(img->width, img->height) : 1;
      spec.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
      nodeTextures_.emplace_back(context, spec);
      uploadRgba8(context, nodeTextures_.back(), img->rgba.data());  // row 0 at v = 0, as GL
      samplers_.push_back(makeSampler(device, t.sampler.filter != TextureFilter::Nearest, addressMode(t.sampler.wrap), mipmapped));
      info.imageView = nodeTextures_.back().view();
    }
    info.sampler = samplers_.back().get();
    images.push_back(info);
    bindings.push_back({static_cast<uint32_t>(t.binding), VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                        VK_SHADER_STAGE_ALL_GRAPHICS, nullptr});
  }

  VkDescriptorSetLayoutCreateInfo lci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  lci.bindingCount = static_cast<uint32_t>(bindings.size());
  lci.pBindings = bindings.data();
  VkDescriptorSetLayout layout = VK_NULL_HANDLE;
  checkVk(vkCreateDescriptorSetLayout(device, &lci, nullptr, &layout), "creating the water's descriptor set layout");
  setLayout_ = VkDescriptorSetLayoutHandle(device, layout);
  if (bindings.empty()) return;

  std::vector<VkDescriptorPoolSize> sizes;
  if (blockSize_ > 0) sizes.push_back({VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1});
  if (!images.empty()) sizes.push_back({VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, static_cast<uint32_t>(images.size())});
  VkDescriptorPoolCreateInfo pci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pci.maxSets = 1;
  pci.poolSizeCount = static_cast<uint32_t>(sizes.size());
  pci.pPoolSizes = sizes.data();
  VkDescriptorPool pool = VK_NULL_HANDLE;
  checkVk(vkCreateDescriptorPool(device, &pci, nullptr, &pool), "creating the descriptor pool");
  pool_ = VkDescriptorPoolHandle(device, pool);
  VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  ai.descriptorPool = pool;
  ai.descriptorSetCount = 1;
  ai.pSetLayouts = &layout;
  checkVk(vkAllocateDescriptorSets(device, &ai, &set_), "allocating the water's descriptor set");

  std::vector<VkWriteDescriptorSet> writes;
  VkDescriptorBufferInfo blockInfo{block_.buffer(), 0, blockSize_};
  size_t image = 0;
  for (const auto& b : bindings) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set_;
    w.dstBinding = b.binding;
    w.descriptorCount = 1;
    w.descriptorType = b.descriptorType;
    if (b.descriptorType == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER) w.pBufferInfo = &blockInfo;
    else w.pImageInfo = &images[image++];
    writes.push_back(w);
  }
  vkUpdateDescriptorSets(device, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
}

void VkWaterBindings::writeUniforms(const FrameValues& frame) {
  if (blockSize_ == 0) return;
  std::vector<unsigned char> bytes(blockSize_, 0);
  for (const Uniform& u : uniforms_) {
    std::vector<float> v = u.isParameter ? u.value : builtinUniformValue(u.builtin, u.angularFrequency, frame);
    unsigned char* at = bytes.data() + u.member.offset;
    switch (u.type) {
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
  block_.write(bytes.data(), bytes.size());
}

void VkWaterBindings::bind(VkCommandBuffer cmd, VkPipelineLayout layout) const {
  if (set_) vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &set_, 0, nullptr);
}

}  // namespace wg::rt
