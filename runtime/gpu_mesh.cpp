// A mesh uploaded to the GL context (runtime/gpu_mesh.h).
#include "runtime/gpu_mesh.h"

#include <cstdint>

namespace wg::rt {

GpuMesh uploadMesh(const Mesh& m, const std::vector<std::pair<GLuint, int>>& attributes) {
  GpuMesh g;
  g.vao = makeVertexArray();
  g.vbo = makeBuffer();
  g.ibo = makeBuffer();
  glBindVertexArray(g.vao.id());
  glBindBuffer(GL_ARRAY_BUFFER, g.vbo.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(m.vertices.size() * sizeof(float)), m.vertices.data(),
               GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.ibo.id());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(m.indices.size() * sizeof(unsigned)),
               m.indices.data(), GL_STATIC_DRAW);
  GLsizei stride = static_cast<GLsizei>(m.floatsPerVertex * sizeof(float));
  int offset = 0;
  for (auto [location, components] : attributes) {
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(static_cast<uintptr_t>(offset * sizeof(float))));
    offset += components;
  }
  glBindVertexArray(0);
  g.indexCount = static_cast<GLsizei>(m.indices.size());
  return g;
}

}  // namespace wg::rt
