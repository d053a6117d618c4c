#pragma once
// A mesh of the built-in scene (runtime/scene.h: the opaque scene, the water grid) in
// Vulkan buffers, as runtime/gpu_mesh.h is for GL: interleaved float vertices and 32-bit
// indices, drawn by the Vulkan renderer.
#include <cstdint>

#include "runtime/scene.h"
#include "runtime/vk_resources.h"

namespace wg::rt {

struct VkMesh {
  VkBufferOwner vertices, indices;
  uint32_t indexCount = 0;
};

VkMesh uploadVkMesh(VkContext& context, const Mesh& m);

}  // namespace wg::rt
