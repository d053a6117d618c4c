#include "accuracy/vk_probe.h"

#include <cstring>
#include <memory>
#include <optional>

#include "accuracy/probe_gpu.h"
#include "codegen/glslang_validate.h"
#include "codegen/shader_interface.h"
#include "codegen/uniform_block_layout.h"
#include "runtime/runtime_error.h"
#include "core/ocean_fft_reference.h"
#include "runtime/vk_ocean_simulation.h"
#include "runtime/vk_pipelines.h"
#include "runtime/vk_resources.h"
#include "runtime/vk_shader_inputs.h"

namespace wg::accuracy {
namespace {

using rt::RuntimeError;

constexpr VkFormat kTargetFormat = VK_FORMAT_R32G32B32A32_SFLOAT;

// GL's probe triangle; Vulkan's y-down clip space does not matter to a triangle that
// covers the whole (one-pixel) viewport.
const char* const kFullscreenVertex =
    "#version 450\n"
    "void main() {\n"
    "  vec2 p = vec2(float((gl_VertexIndex & 1) << 2) - 1.0, float((gl_VertexIndex & 2) << 1) - 1.0);\n"
    "  gl_Position = vec4(p, 0.0, 1.0);\n"
    "}\n";

std::vector<rt::VkShaderCode> compileProbe(const std::string& fragmentText, const std::string& what) {
  ValidationResult r = validateShaders(Target::Vk450, {{ShaderStage::Vertex, "probe fullscreen.vert", kFullscreenVertex},
                                                       {ShaderStage::Fragment, what, fragmentText}});
  if (!r.ok) {
    std::string text = what + ": glslang rejects the vk450 probe shader:";
    for (const auto& e : r.errors) text += "\n  " + e.fileName + ":" + std::to_string(e.line) + ": " + e.text;
    throw RuntimeError(RuntimeError::Kind::Driver, text);
  }
  return {{ShaderStage::Vertex, "probe fullscreen.vert", std::move(r.spirv[0])}, {ShaderStage::Fragment, what, std::move(r.spirv[1])}};
}

std::vector<float> floats(const Value& v, Type type) {
  std::vector<float> out(static_cast<size_t>(componentCount(type)));
  for (size_t i = 0; i < out.size(); ++i) out[i] = static_cast<float>(v.c[i]);
  return out;
}

}  // namespace

namespace {

std::vector<std::array<float, 4>> drawCases(rt::VkContext& context, const EmitResult& shader, const Program& program,
                                            const std::vector<ProbeCase>& cases, const std::string& what) {
  const EmittedShader* frag = nullptr;
  for (const auto& s : shader.shaders)
    if (s.stage == ShaderStage::Fragment) frag = &s;
  if (!frag) throw RuntimeError(RuntimeError::Kind::Manifest, what + ": no fragment shader to probe");
  std::vector<rt::VkShaderCode> stages = compileProbe(frag->text, what);
  const VkDevice device = context.device();

  // The block: every uniform in declaration order at its std140 offset, one copy per case.
  std::vector<BlockMember> members;
  size_t end = 0;
  for (const UniformInfo& u : shader.uniforms) {
    members.push_back(std140Member(end, u.type));
    end = members.back().offset + members.back().size;
  }
  const size_t blockSize = std140BlockSize(members);
  VkPhysicalDeviceProperties properties;
  vkGetPhysicalDeviceProperties(context.physicalDevice(), &properties);
  const size_t align = std::max<size_t>(1, properties.limits.minUniformBufferOffsetAlignment);
  const size_t stride = (blockSize + align - 1) / align * align;
  rt::VkBufferOwner blocks;
  if (blockSize > 0) {
    std::vector<unsigned char> bytes(stride * cases.size(), 0);
    for (size_t i = 0; i < cases.size(); ++i)
      for (size_t k = 0; k < shader.uniforms.size(); ++k) {
        const UniformInfo& u = shader.uniforms[k];
        rt::writeBlockMember(bytes.data() + i * stride, members[k], u.type,
                             floats(probeUniformValue(u, program, cases[i], i), u.type));
      }
    blocks = rt::VkBufferOwner(context, bytes.size(), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    blocks.write(bytes.data(), bytes.size());
  }

  // Samplers at their bindings: node textures as the renderer loads them; scene textures
  // 1x1 float images, nearest (every fetch returns the texel), refilled per case from
  // `texels` (per case, per scene texture, per layer: one RGBA32F texel).
  std::vector<rt::VkNodeTexture> nodeTextures;
  struct SceneTexture {
    const TextureInfo* info;
    rt::VkImageOwner image;
    size_t firstTexel;
  };
  std::vector<SceneTexture> sceneTextures;
  rt::VkSamplerHandle nearest = rt::makeVkSampler(device, false, VK_SAMPLER_ADDRESS_MODE_REPEAT, false);
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  std::vector<VkDescriptorImageInfo> images;
  size_t texelsPerCase = 0;
  // The ocean maps come from the Vulkan simulation, recorded at each case's time as GL's
  // probe updates its own (probe_gpu.cpp).
  std::unique_ptr<rt::VkOceanSimulation> oceans;
  if (!shader.oceans.empty()) oceans = std::make_unique<rt::VkOceanSimulation>(context, shader.oceans, shader.textures);
  for (const TextureInfo& t : shader.textures) {
    VkDescriptorImageInfo info{};
    info.imageLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    if (t.ocean) {
      if (!oceans) throw RuntimeError(RuntimeError::Kind::Manifest, what + ": an ocean map without an ocean");
      info.imageView = oceans->map(*t.ocean).view();
      info.sampler = nearest.get();
    } else if (t.scene) {
      const bool cube = t.type == Type::SamplerCube;
      rt::VkImageSpec spec;
      spec.format = kTargetFormat;
      spec.layers = cube ? 6 : 1;
      spec.cube = cube;
      spec.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
      sceneTextures.push_back({&t, rt::VkImageOwner(context, spec), texelsPerCase});
      texelsPerCase += spec.layers;
      info.imageView = sceneTextures.back().image.view();
      info.sampler = nearest.get();
    } else {
      nodeTextures.push_back(rt::loadVkNodeTexture(context, t, program.directory, what));
      info.imageView = nodeTextures.back().image.view();
      info.sampler = nodeTextures.back().sampler.get();
    }
    images.push_back(info);
    bindings.push_back({static_cast<uint32_t>(t.binding), VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                        VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
  }
  rt::VkBufferOwner texels;
  if (texelsPerCase > 0) {
    std::vector<float> values(cases.size() * texelsPerCase * 4);
    for (size_t i = 0; i < cases.size(); ++i)
      for (const SceneTexture& s : sceneTextures) {
        std::array<float, 4> texel = sceneSamplerRow(*s.info->scene).caseTexel(cases[i].env);
        for (uint32_t layer = 0; layer < s.image.spec().layers; ++layer)
          std::memcpy(&values[((i * texelsPerCase) + s.firstTexel + layer) * 4], texel.data(), sizeof texel);
      }
    texels = rt::VkBufferOwner(context, values.size() * sizeof(float), VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    texels.write(values.data(), values.size() * sizeof(float));
  }
  if (blockSize > 0)
    bindings.push_back({static_cast<uint32_t>(iface::kUniformBlockBinding), VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1,
                        VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});

  VkDescriptorSetLayoutCreateInfo lci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  lci.bindingCount = static_cast<uint32_t>(bindings.size());
  lci.pBindings = bindings.data();
  VkDescriptorSetLayout setLayoutRaw = VK_NULL_HANDLE;
  rt::checkVk(vkCreateDescriptorSetLayout(device, &lci, nullptr, &setLayoutRaw), "creating the probe's descriptor set layout");
  rt::VkDescriptorSetLayoutHandle setLayout(device, setLayoutRaw);
  VkPipelineLayoutCreateInfo pli{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  pli.setLayoutCount = 1;
  pli.pSetLayouts = &setLayoutRaw;
  VkPipelineLayout pipelineLayoutRaw = VK_NULL_HANDLE;
  rt::checkVk(vkCreatePipelineLayout(device, &pli, nullptr, &pipelineLayoutRaw), "creating the probe's pipeline layout");
  rt::VkPipelineLayoutHandle pipelineLayout(device, pipelineLayoutRaw);

  rt::VkDescriptorPoolHandle pool;
  VkDescriptorSet set = VK_NULL_HANDLE;
  if (!bindings.empty()) {
    std::vector<VkDescriptorPoolSize> sizes;
    if (blockSize > 0) sizes.push_back({VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1});
    if (!images.empty()) sizes.push_back({VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, static_cast<uint32_t>(images.size())});
    VkDescriptorPoolCreateInfo pci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pci.maxSets = 1;
    pci.poolSizeCount = static_cast<uint32_t>(sizes.size());
    pci.pPoolSizes = sizes.data();
    VkDescriptorPool poolRaw = VK_NULL_HANDLE;
    rt::checkVk(vkCreateDescriptorPool(device, &pci, nullptr, &poolRaw), "creating the probe's descriptor pool");
    pool = rt::VkDescriptorPoolHandle(device, poolRaw);
    VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    ai.descriptorPool = poolRaw;
    ai.descriptorSetCount = 1;
    ai.pSetLayouts = &setLayoutRaw;
    rt::checkVk(vkAllocateDescriptorSets(device, &ai, &set), "allocating the probe's descriptor set");
    std::vector<VkWriteDescriptorSet> writes;
    VkDescriptorBufferInfo blockInfo{blocks.buffer(), 0, blockSize};
    for (size_t k = 0; k < bindings.size(); ++k) {
      VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
      w.dstSet = set;
      w.dstBinding = bindings[k].binding;
      w.descriptorCount = 1;
      w.descriptorType = bindings[k].descriptorType;
      if (w.descriptorType == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC) w.pBufferInfo = &blockInfo;
      else w.pImageInfo = &images[k];
      writes.push_back(w);
    }
    vkUpdateDescriptorSets(device, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
  }

  rt::VkPipelineDescription pd;
  pd.stages = std::move(stages);
  pd.depthTest = false;
  pd.depthWrite = false;
  pd.colorFormats = {kTargetFormat};
  pd.layout = pipelineLayoutRaw;
  rt::VkPipelineHandle pipeline = rt::createGraphicsPipeline(device, pd, what);

  // The target: up to 1024 cases per row; framebuffer row y holds the cases GL draws into
  // window row y, so gl_FragCoord (and u_probe_pixel) are the same in both APIs.
  const auto width = static_cast<uint32_t>(std::min<size_t>(cases.size(), 1024));
  const auto height = static_cast<uint32_t>((cases.size() + 1023) / 1024);
  rt::VkImageSpec targetSpec;
  targetSpec.format = kTargetFormat;
  targetSpec.width = width;
  targetSpec.height = height;
  targetSpec.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  rt::VkImageOwner target(context, targetSpec);

  context.submit([&](VkCommandBuffer cmd) {
    for (auto& s : sceneTextures) s.image.transition(cmd, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    target.transition(cmd, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    bool rendering = false, cleared = false;
    auto beginRendering = [&] {
      VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
      color.imageView = target.layerView(0);
      color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
      color.loadOp = cleared ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_CLEAR;
      color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
      VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
      ri.renderArea = {{0, 0}, {width, height}};
      ri.layerCount = 1;
      ri.colorAttachmentCount = 1;
      ri.pColorAttachments = &color;
      vkCmdBeginRendering(cmd, &ri);
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.get());
      rendering = cleared = true;
    };
    std::optional<std::uint32_t> oceanTime;  // the loop fraction the maps hold
    for (size_t i = 0; i < cases.size(); ++i) {
      if (oceans && oceanTime != ocean::loopFraction(cases[i].env.time[0])) {
        if (rendering) vkCmdEndRendering(cmd), rendering = false;
        oceans->record(cmd, cases[i].env.time[0]);
        oceanTime = ocean::loopFraction(cases[i].env.time[0]);
      }
      if (!sceneTextures.empty()) {
        // The case's texels: copies happen outside rendering, after the last draw read the images.
        if (rendering) vkCmdEndRendering(cmd), rendering = false;
        for (auto& s : sceneTextures) {
          s.image.transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
          VkBufferImageCopy region{};
          region.bufferOffset = ((i * texelsPerCase) + s.firstTexel) * 16;
          region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, s.image.spec().layers};
          region.imageExtent = {1, 1, 1};
          vkCmdCopyBufferToImage(cmd, texels.buffer(), s.image.image(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
          s.image.transition(cmd, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
        }
      }
      if (!rendering) beginRendering();
      if (set) {
        const auto offset = static_cast<uint32_t>(i * stride);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayoutRaw, 0, 1, &set, blockSize > 0 ? 1 : 0,
                                &offset);
      }
      const auto x = static_cast<int32_t>(i % 1024), y = static_cast<int32_t>(i / 1024);
      VkViewport viewport{static_cast<float>(x), static_cast<float>(y), 1.0f, 1.0f, 0.0f, 1.0f};
      VkRect2D scissor{{x, y}, {1, 1}};
      vkCmdSetViewport(cmd, 0, 1, &viewport);
      vkCmdSetScissor(cmd, 0, 1, &scissor);
      vkCmdDraw(cmd, 3, 1, 0, 0);
    }
    if (rendering) vkCmdEndRendering(cmd);
  });
  context.throwOnValidationMessages("probing " + what);
  std::vector<unsigned char> bytes = rt::readBack(context, target);
  context.throwOnValidationMessages("reading the probe image of " + what);
  std::vector<std::array<float, 4>> out(cases.size());
  for (size_t i = 0; i < cases.size(); ++i) std::memcpy(out[i].data(), bytes.data() + i * 16, 16);
  return out;
}

}  // namespace

std::vector<std::array<float, 4>> runProbeOnVulkan(rt::VkContext& context, const EmitResult& shader, const Program& program,
                                                   const std::vector<ProbeCase>& cases, const std::string& what) {
  if (cases.empty()) return {};
  std::vector<std::array<float, 4>> out = drawCases(context, shader, program, cases, what);
  context.throwOnValidationMessages("destroying the probe objects of " + what);  // they are gone now
  return out;
}

}  // namespace wg::accuracy
