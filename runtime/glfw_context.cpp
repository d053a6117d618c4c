#include "runtime/glfw_context.h"

#include <dlfcn.h>

#include <epoxy/gl.h>  // before GLFW, which then includes no GL header of its own
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "runtime/runtime_error.h"

#if defined(__SANITIZE_ADDRESS__)
#define WG_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define WG_ASAN 1
#endif
#endif

namespace wg::rt {
namespace {

// Sanitizer builds only: GLFW dlopens the X extension libraries, and closing the X display
// unloads Mesa's DRI driver (which the GLX context loaded). What they allocated and never
// freed is then reported from an unloaded, nameless module that no LeakSanitizer
// suppression can match; pinned (never unloaded), each keeps its name and
// tests/robustness/lsan.supp applies. A library that is not there is simply skipped.
void pinWindowSystemLibraries() {
#ifdef WG_ASAN
  for (const char* lib : {"libXi.so.6", "libXrandr.so.2", "libXinerama.so.1", "libXcursor.so.1", "libXxf86vm.so.1",
                          "/usr/lib/x86_64-linux-gnu/dri/swrast_dri.so"})
    dlopen(lib, RTLD_LAZY | RTLD_NODELETE);
#endif
}

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
  pinWindowSystemLibraries();
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
