#pragma once
// A headless GL context on EGL's surfaceless platform (Mesa llvmpipe on any machine):
// desktop OpenGL 4.5 core for glsl330 shaders, or OpenGL ES 3.2 for es300 shaders. It
// renders only into framebuffer objects. GL entry points are called through libepoxy,
// which dispatches to whichever context is current, so both APIs can live in one process.
#include <memory>
#include <string>

namespace wg::rt {

enum class GlApi { DesktopGl45, Es32 };

const char* apiName(GlApi api);  // "OpenGL 4.5 core", "OpenGL ES 3.2"

class EglContext {
 public:
  // Creates the context and makes it current on this thread. Throws RuntimeError
  // (Kind::Environment) with one line naming what is missing: the EGL library, the
  // surfaceless platform extension, the display, the API or the context version.
  static std::unique_ptr<EglContext> create(GlApi api);
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  void makeCurrent();
  GlApi api() const { return api_; }
  bool isEs() const { return api_ == GlApi::Es32; }
  // GL_RENDERER and GL_VERSION of the current context, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  std::string renderer() const;
  std::string version() const;
  bool hasExtension(const char* name) const;

 private:
  EglContext() = default;
  GlApi api_ = GlApi::DesktopGl45;
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
};

}  // namespace wg::rt
