#pragma once
// A mesh (runtime/scene.h) uploaded to the GL context: its vertex array, vertex and index
// buffers.
#include <utility>
#include <vector>

#include "runtime/gl_resources.h"
#include "runtime/scene.h"

namespace wg::rt {

struct GpuMesh {
  VertexArray vao;
  Buffer vbo, ibo;
  GLsizei indexCount = 0;
};

// Uploads `m` with one float attribute per (location, components), in vertex order.
GpuMesh uploadMesh(const Mesh& m, const std::vector<std::pair<GLuint, int>>& attributes);

}  // namespace wg::rt
