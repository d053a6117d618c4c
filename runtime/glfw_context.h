#pragma once
// A window with a desktop OpenGL 4.5 core context, made by GLFW, for the editor. The
// Renderer draws into it exactly as into the headless EGL context (see gl_context.h):
// only who creates the context differs. Lives in its own library (wg_runtime_window) so
// the `watergraph` command does not link GLFW.
#include <memory>
#include <string>

#include "runtime/gl_context.h"

struct GLFWwindow;

namespace wg::rt {

struct WindowOptions {
  int width = 1280, height = 720;
  std::string title = "watergraph";
  bool visible = true;
  bool vsync = true;
};

class GlfwContext : public GlContext {
 public:
  // Opens the window and makes its context current. Throws RuntimeError
  // (Kind::Environment) with one line when there is no display or no GL 4.5 core context.
  static std::unique_ptr<GlfwContext> create(const WindowOptions& options);
  ~GlfwContext() override;

  void makeCurrent() override;
  GLFWwindow* window() const { return window_; }
  bool shouldClose() const;
  void swapBuffers();
  // The default framebuffer's size in pixels.
  void framebufferSize(int* width, int* height) const;

 private:
  GlfwContext() : GlContext(GlApi::DesktopGl45) {}
  GLFWwindow* window_ = nullptr;
};

}  // namespace wg::rt
