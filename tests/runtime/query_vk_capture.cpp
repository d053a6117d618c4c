#include "query_vk_capture.h"

#include <cmath>
#include <cstring>
#include <limits>

#include "codegen/glslang_validate.h"
#include "codegen/shader_interface.h"
#include "codegen/uniform_block_layout.h"
#include "runtime/runtime_error.h"
#include "runtime/uniform_values.h"
#include "runtime/vk_context.h"
#include "runtime/vk_pipelines.h"
#include "runtime/vk_resources.h"
#include "runtime/vk_shader_inputs.h"

namespace wg::rt {
namespace {

// The WgUniforms block at time t, as VkWaterBindings::writeUniforms fills it, with
// `viewProjection` for the camera and the parameter values `host` sets.
std::vector<unsigned char> queryCaptureBlock(const Manifest& manifest, double t, const glm::mat4& viewProjection,
                                             const std::map<std::string, std::vector<double>>& host) {
  FrameValues frame;
  frame.time = t;
  frame.viewProjection = viewProjection;
  std::vector<BlockMember> members;
  std::vector<std::vector<float>> values;
  size_t end = 0;
  for (const ManifestUniform& u : manifest.uniforms) {
    members.push_back(std140Member(end, u.type));
    end = members.back().offset + members.back().size;
    std::vector<float> v;
    if (u.parameter) {
      auto set = host.find(u.parameter->name);
      const std::vector<double>& value = set != host.end() ? set->second : u.parameter->defaultValue;
      v.assign(value.begin(), value.end());
      const float inf = std::numeric_limits<float>::infinity();
      clampIntoRange(v, u.parameter->min ? static_cast<float>(*u.parameter->min) : -inf,
                     u.parameter->max ? static_cast<float>(*u.parameter->max) : inf);
    }
    values.push_back(std::move(v));
  }
  std::vector<unsigned char> block((end + 15) / 16 * 16, 0);
  for (size_t i = 0; i < manifest.uniforms.size(); ++i) {
    const ManifestUniform& u = manifest.uniforms[i];
    std::vector<float> v = u.parameter ? values[i] : builtinUniformValue(u.builtin, u.angularFrequency, frame);
    writeBlockMember(block.data(), members[i], u.type, v);
  }
  return block;
}

// The varying index (= location) the vertex stage writes the displaced position at.
int worldPositionLocation(const Manifest& manifest) {
  for (size_t i = 0; i < manifest.varyings.size(); ++i)
    if (manifest.varyings[i].name == "v_world_position") return static_cast<int>(i);
  return -1;
}

}  // namespace

VkCapturedPoints captureVulkanVertexStage(const std::vector<uint32_t>& vertexSpirv, const Manifest& manifest,
                                          const std::vector<std::pair<double, double>>& points, double t,
                                          const std::map<std::string, std::vector<double>>& host) {
  VkCapturedPoints out;
  const int location = worldPositionLocation(manifest);
  if (location < 0) {
    out.error = "the vertex stage passes no v_world_position on (the fragment stage reads no world position), so there is nothing to capture";
    return out;
  }
  ValidationResult fragment = validateShaders(
      Target::Vk450, {{ShaderStage::Fragment, "query_capture.frag",
                       "#version 450\nlayout(location = " + std::to_string(location) +
                           ") flat in vec3 v_world_position;\nlayout(location = 0) out vec4 o_captured;\n"
                           "void main() { o_captured = vec4(v_world_position, 1.0); }\n"}});
  if (!fragment.ok || fragment.spirv.empty()) {
    out.error = "the capture fragment shader does not compile";
    return out;
  }
  try {
    auto context = VkContext::create({});
    const VkDevice device = context->device();
    // Every point shrunk to its viewport's middle (|x|, |y| < 1e-6 * 1e3 in clip space for
    // points within a kilometre), at depth 0.5, w = 1 (no perspective: the flat input is
    // the vertex's value).
    glm::mat4 shrink(0.0f);
    shrink[0][0] = 1e-6f;
    shrink[1][1] = 1e-6f;
    shrink[3][2] = 0.5f;
    shrink[3][3] = 1.0f;
    std::vector<unsigned char> blockBytes = queryCaptureBlock(manifest, t, shrink, host);
    VkBufferOwner block(*context, std::max<size_t>(blockBytes.size(), 16), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    if (!blockBytes.empty()) block.write(blockBytes.data(), blockBytes.size());

    VkDescriptorSetLayoutBinding binding{static_cast<uint32_t>(iface::kUniformBlockBinding), VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                         1, VK_SHADER_STAGE_VERTEX_BIT, nullptr};
    VkDescriptorSetLayoutCreateInfo lci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    lci.bindingCount = 1;
    lci.pBindings = &binding;
    VkDescriptorSetLayout rawSetLayout = VK_NULL_HANDLE;
    checkVk(vkCreateDescriptorSetLayout(device, &lci, nullptr, &rawSetLayout), "creating the capture's set layout");
    VkDescriptorSetLayoutHandle setLayout(device, rawSetLayout);
    VkDescriptorSet set = VK_NULL_HANDLE;
    VkDescriptorPoolHandle pool =
        allocateSingleSet(device, rawSetLayout, {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1}}, &set, "the query capture");
    VkDescriptorBufferInfo blockInfo{block.buffer(), 0, block.size()};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = set;
    write.dstBinding = binding.binding;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    write.pBufferInfo = &blockInfo;
    vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);

    VkPipelineLayoutCreateInfo pli{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    pli.setLayoutCount = 1;
    pli.pSetLayouts = &rawSetLayout;
    VkPipelineLayout rawLayout = VK_NULL_HANDLE;
    checkVk(vkCreatePipelineLayout(device, &pli, nullptr, &rawLayout), "creating the capture's pipeline layout");
    VkPipelineLayoutHandle layout(device, rawLayout);

    // The water grid's interleaved vertex (position, normal, uv), at the manifest's locations.
    VkPipelineDescription d;
    d.stages = {{ShaderStage::Vertex, "query capture vertex", vertexSpirv},
                {ShaderStage::Fragment, "query_capture.frag", fragment.spirv[0]}};
    d.vertexStride = 32;
    for (const AttributeInfo& a : manifest.attributes) {
      if (a.name == iface::kPositionAttribute) d.attributes.push_back({static_cast<uint32_t>(a.location), 0, VK_FORMAT_R32G32B32_SFLOAT, 0});
      else if (a.name == iface::kNormalAttribute) d.attributes.push_back({static_cast<uint32_t>(a.location), 0, VK_FORMAT_R32G32B32_SFLOAT, 12});
      else if (a.name == iface::kUvAttribute) d.attributes.push_back({static_cast<uint32_t>(a.location), 0, VK_FORMAT_R32G32_SFLOAT, 24});
    }
    d.points = true;
    d.depthTest = false;
    d.depthWrite = false;
    d.colorFormats = {VK_FORMAT_R32G32B32A32_SFLOAT};
    d.layout = rawLayout;
    VkPipelineHandle pipeline = createGraphicsPipeline(device, d, "the query capture");

    const uint32_t count = static_cast<uint32_t>(points.size());
    std::vector<float> vertices;
    for (const auto& [x0, z0] : points)
      vertices.insert(vertices.end(), {static_cast<float>(x0), 0.0f, static_cast<float>(z0), 0.0f, 1.0f, 0.0f, 0.5f, 0.5f});
    VkBufferOwner vertexBuffer(*context, vertices.size() * sizeof(float), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    vertexBuffer.write(vertices.data(), vertices.size() * sizeof(float));

    VkImageSpec spec;
    spec.format = VK_FORMAT_R32G32B32A32_SFLOAT;
    spec.width = count;
    spec.height = 1;
    spec.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    VkImageOwner target(*context, spec);
    context->submit([&](VkCommandBuffer cmd) {
      target.transition(cmd, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
      VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
      color.imageView = target.layerView(0);
      color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
      color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
      color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
      // A point that draws nothing reads back as NaN, which no bound accepts.
      const float nan = std::numeric_limits<float>::quiet_NaN();
      color.clearValue.color = {{nan, nan, nan, nan}};
      VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
      ri.renderArea = {{0, 0}, {count, 1}};
      ri.layerCount = 1;
      ri.colorAttachmentCount = 1;
      ri.pColorAttachments = &color;
      vkCmdBeginRendering(cmd, &ri);
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.get());
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, rawLayout, 0, 1, &set, 0, nullptr);
      VkDeviceSize offset = 0;
      VkBuffer vb = vertexBuffer.buffer();
      vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &offset);
      for (uint32_t k = 0; k < count; ++k) {
        VkViewport viewport{static_cast<float>(k), 0.0f, 1.0f, 1.0f, 0.0f, 1.0f};
        VkRect2D scissor{{static_cast<int32_t>(k), 0}, {1, 1}};
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        vkCmdSetScissor(cmd, 0, 1, &scissor);
        vkCmdDraw(cmd, 1, 1, k, 0);
      }
      vkCmdEndRendering(cmd);
    });
    std::vector<unsigned char> texels = readBack(*context, target);
    if (texels.size() != static_cast<size_t>(count) * 16) {
      out.error = "read back " + std::to_string(texels.size()) + " bytes";
      return out;
    }
    for (uint32_t k = 0; k < count; ++k) {
      float rgba[4];
      std::memcpy(rgba, texels.data() + 16 * k, sizeof rgba);
      out.positions.insert(out.positions.end(), {rgba[0], rgba[1], rgba[2]});
    }
  } catch (const std::exception& e) {
    out.error = e.what();
  }
  return out;
}

}  // namespace wg::rt
