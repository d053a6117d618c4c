#include "runtime/vk_water_bindings.h"

#include <algorithm>
#include <limits>

#include "codegen/shader_interface.h"
#include "runtime/runtime_error.h"

namespace wg::rt {
VkWaterBindings::VkWaterBindings(VkContext& context, const Manifest& manifest,
                                 const std::function<SceneImage(SceneSampler)>& sceneImage,
                                 const std::function<VkImageOwner*(const OceanMapRef&)>& oceanMap,
                                 const std::map<std::string, TextureOrigin>& origins) {
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
    if (t.ocean) {
      VkImageOwner* map = oceanMap(*t.ocean);
      if (!map) manifestError("texture " + t.name + " is an ocean map, but the manifest lists no ocean_simulation pass");
      if (t.type != Type::Sampler2D) manifestError("ocean map " + t.name + " must be a sampler2D, not " + std::string(typeName(t.type)));
      samplers_.push_back(makeVkSampler(device, false, VK_SAMPLER_ADDRESS_MODE_REPEAT, false));
      info.imageView = map->view();
    } else if (t.scene) {
      SceneImage s = sceneImage(*t.scene);
      if (!s.image)
        manifestError("texture " + t.name + " (scene resource '" +
                      std::string(sceneResourceRow(sceneSamplerRow(*t.scene).resource).name) +
                      "') is not rendered by any pass the manifest lists");
      if (cube != s.image->spec().cube) manifestError("texture " + t.name + " has the wrong sampler type " + std::string(typeName(t.type)));
      samplers_.push_back(makeVkSampler(device, !s.nearest, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, false));
      info.imageView = s.image->view();
      if (std::find(sceneImages_.begin(), sceneImages_.end(), s.image) == sceneImages_.end()) sceneImages_.push_back(s.image);
    } else {
      if (t.type != Type::Sampler2D) manifestError("node texture " + t.name + " must be a sampler2D, not " + std::string(typeName(t.type)));
      auto o = origins.find(t.source);
      std::string dir = o != origins.end() ? o->second.graphDir : ".";
      std::string owner = o != origins.end() ? o->second.owner : "texture " + t.name;
      VkNodeTexture loaded = loadVkNodeTexture(context, t, dir, owner);
      nodeTextures_.push_back(std::move(loaded.image));
      samplers_.push_back(std::move(loaded.sampler));
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
  pool_ = allocateSingleSet(device, layout, sizes, &set_, "the water");

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
  for (const Uniform& u : uniforms_)
    writeBlockMember(bytes.data(), u.member, u.type,
                     u.isParameter ? u.value : builtinUniformValue(u.builtin, u.angularFrequency, frame));
  block_.write(bytes.data(), bytes.size());
}

void VkWaterBindings::bind(VkCommandBuffer cmd, VkPipelineLayout layout) const {
  if (set_) vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &set_, 0, nullptr);
}

}  // namespace wg::rt
