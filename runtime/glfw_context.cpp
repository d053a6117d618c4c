#include "runtime/glfw_context.h"

#include <epoxy/gl.h>  // before GLFW, which then includes no GL header of its own
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "runtime/runtime_error.h"

namespace wg::rt {
namespace {

// GLFW reports why through a callback; the latest message becomes part of our one line.
std::string& lastGlfwError() {
  static std::string message;
  return message;
}

void onGlfwError(int code, const char* description) {
  lastGlfwError() = description ? description : "GLFW error " + std::to_string(code);
}

[[noreturn]] void fail(const std::string& what) {
  std::string why = lastGlfwError();
  throw RuntimeError(RuntimeError::Kind::Environment, what + (why.empty() ? "" : " (" + why + ")"));
}

}  // namespace

std::unique_ptr<GlfwContext> GlfwContext::create(const WindowOptions& options) {
  glfwSetErrorCallback(onGlfwError);
  lastGlfwError().clear();
  if (!glfwInit()) fail("cannot open a window: no display; run it on a desktop or under xvfb-run");
  glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
  GLFWwindow* w = glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
  if (!w) {
    glfwTerminate();
    fail("cannot open a window with an OpenGL 4.5 core context");
  }
  std::unique_ptr<GlfwContext> c(new GlfwContext());
  c->window_ = w;
  c->makeCurrent();
  glfwSwapInterval(options.vsync ? 1 : 0);
  return c;
}

GlfwContext::~GlfwContext() {
  if (window_) glfwDestroyWindow(window_);
  glfwTerminate();
}

void GlfwContext::makeCurrent() { glfwMakeContextCurrent(window_); }

bool GlfwContext::shouldClose() const { return glfwWindowShouldClose(window_); }

void GlfwContext::swapBuffers() { glfwSwapBuffers(window_); }

void GlfwContext::framebufferSize(int* width, int* height) const { glfwGetFramebufferSize(window_, width, height); }

}  // namespace wg::rt
