// The built-in scene's meshes in Vulkan buffers (runtime/vk_mesh.h).
#include "runtime/vk_mesh.h"

namespace wg::rt {

VkMesh uploadVkMesh(VkContext& context, const Mesh& m) {
  VkMesh g;
  g.vertices = VkBufferOwner(context, m.vertices.size() * sizeof(float), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  g.vertices.write(m.vertices.data(), g.vertices.size());
  g.indices = VkBufferOwner(context, m.indices.size() * sizeof(unsigned), VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  g.indices.write(m.indices.data(), g.indices.size());
  g.indexCount = static_cast<uint32_t>(m.indices.size());
  return g;
}

}  // namespace wg::rt
