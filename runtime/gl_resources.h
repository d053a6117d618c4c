#pragma once
// Move-only owners of GL objects (shaders, programs, buffers, vertex arrays, textures,
// framebuffers). Each deletes its object when it goes out of scope; the context must be
// current then. Program creation reports the driver's compile and link logs.
#include <string>
#include <utility>
#include <vector>

#include <epoxy/gl.h>

namespace wg::rt {

template <void (*Delete)(GLuint)>
class GlHandle {
 public:
  GlHandle() = default;
  explicit GlHandle(GLuint id) : id_(id) {}
  ~GlHandle() { reset(); }
  GlHandle(GlHandle&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  GlHandle& operator=(GlHandle&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  GlHandle(const GlHandle&) = delete;
  GlHandle& operator=(const GlHandle&) = delete;
  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_) Delete(id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
};

namespace detail {
void deleteShader(GLuint id);
void deleteProgram(GLuint id);
void deleteBuffer(GLuint id);
void deleteVertexArray(GLuint id);
void deleteTexture(GLuint id);
void deleteFramebuffer(GLuint id);
}  // namespace detail

using Shader = GlHandle<detail::deleteShader>;
using Program = GlHandle<detail::deleteProgram>;
using Buffer = GlHandle<detail::deleteBuffer>;
using VertexArray = GlHandle<detail::deleteVertexArray>;
using Texture = GlHandle<detail::deleteTexture>;
using Framebuffer = GlHandle<detail::deleteFramebuffer>;

Buffer makeBuffer();
VertexArray makeVertexArray();
Texture makeTexture();
Framebuffer makeFramebuffer();

// Node textures (with their sampler state): runtime/node_texture.h.

struct ShaderSource {
  GLenum stage;      // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, ...
  std::string name;  // shown in errors: "lake.glsl330.frag"
  std::string text;
};

// Compiles and links; attribute locations come from the shaders' layout qualifiers. On a
// compile or link failure throws RuntimeError(Kind::Driver) whose message names the file
// and carries the driver's log, e.g.
//   "the GL driver (llvmpipe) rejected lake.es300.frag, which glslang accepted:\n0:12(3): error: ..."
Program linkProgram(const std::vector<ShaderSource>& sources, const std::string& what);

// Throws RuntimeError(Kind::Driver) naming `where` when glGetError reports an error.
void checkGl(const char* where);

}  // namespace wg::rt
