#pragma once
// What the Renderer needs from a GL context, whoever made it: the headless EGL context
// (egl_context.h) for `watergraph render` and the tests, or the GLFW window
// (glfw_context.h) for the editor. GL is called through libepoxy, which dispatches to
// whichever context is current, so the Renderer and everything else in runtime/ is the
// same code on both.
#include <string>

namespace wg::rt {

enum class GlApi { DesktopGl45, Es32 };

const char* apiName(GlApi api);  // "OpenGL 4.5 core", "OpenGL ES 3.2"

class GlContext {
 public:
  virtual ~GlContext() = default;
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // Throws RuntimeError(Kind::Environment) when the context cannot be made current.
  virtual void makeCurrent() = 0;
  GlApi api() const { return api_; }
  bool isEs() const { return api_ == GlApi::Es32; }
  // GL_RENDERER and GL_VERSION of the current context, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  std::string renderer() const;
  std::string version() const;
  bool hasExtension(const char* name) const;

 protected:
  explicit GlContext(GlApi api) : api_(api) {}

 private:
  GlApi api_;
};

}  // namespace wg::rt
