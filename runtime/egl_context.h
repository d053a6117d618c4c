#pragma once
// A headless GL context on EGL's surfaceless platform (Mesa llvmpipe on any machine):
// desktop OpenGL 4.5 core for glsl330 shaders, or OpenGL ES 3.2 for es300 shaders. It
// renders only into framebuffer objects. GL entry points are called through libepoxy,
// which dispatches to whichever context is current, so both APIs can live in one process.
#include <memory>
#include <string>

#include "runtime/gl_context.h"

namespace wg::rt {

class EglContext : public GlContext {
 public:
  // Creates the context and makes it current on this thread. Throws RuntimeError
  // (Kind::Environment) with one line naming what is missing: the EGL library, the
  // surfaceless platform extension, the display, the API or the context version.
  static std::unique_ptr<EglContext> create(GlApi api);
  ~EglContext() override;

  void makeCurrent() override;

 private:
  explicit EglContext(GlApi api) : GlContext(api) {}
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
};

}  // namespace wg::rt
