#include "runtime/egl_context.h"

#include <dlfcn.h>

#include <cstring>
#include <cstdio>
#include <string>
#include <vector>

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include "runtime/runtime_error.h"

namespace wg::rt {
namespace {

[[noreturn]] void fail(const std::string& what) { throw RuntimeError(RuntimeError::Kind::Environment, what); }

std::string eglErrorName(EGLint e) {
  switch (e) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    default: return "EGL error 0x" + [&] { char b[16]; std::snprintf(b, sizeof b, "%04x", e); return std::string(b); }();
  }
}

bool hasWord(const char* list, const char* word) {
  if (!list) return false;
  size_t n = std::strlen(word);
  for (const char* p = list; (p = std::strstr(p, word)); p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

// The surfaceless display, initialised once per process (EGL displays are not reference
// counted, so it is never terminated while contexts may come and go).
EGLDisplay surfacelessDisplay() {
  static EGLDisplay display = EGL_NO_DISPLAY;
  if (display != EGL_NO_DISPLAY) return display;
  // libepoxy loads libEGL lazily and aborts when it is missing; check first so the user
  // gets one line and exit 2 instead.
  if (!dlopen("libEGL.so.1", RTLD_LAZY | RTLD_GLOBAL))
    fail("cannot render: the EGL library libEGL.so.1 is not installed (Debian: libegl1 and libegl-mesa0)");
  const char* clientExt = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!hasWord(clientExt, "EGL_EXT_platform_base"))
    fail("cannot render: libEGL found no EGL driver that offers headless displays (no EGL_EXT_platform_base; "
         "Debian: libegl-mesa0)");
  if (!hasWord(clientExt, "EGL_MESA_platform_surfaceless"))
    fail("cannot render: EGL has no surfaceless platform (EGL_MESA_platform_surfaceless; Debian: libegl-mesa0)");
  EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (d == EGL_NO_DISPLAY) fail("cannot render: no EGL surfaceless display (" + eglErrorName(eglGetError()) + ")");
  EGLint major = 0, minor = 0;
  if (!eglInitialize(d, &major, &minor))
    fail("cannot render: eglInitialize failed on the surfaceless display (" + eglErrorName(eglGetError()) +
         "; is a Mesa driver such as libgl1-mesa-dri installed?)");
  const char* ext = eglQueryString(d, EGL_EXTENSIONS);
  if (!hasWord(ext, "EGL_KHR_surfaceless_context"))
    fail("cannot render: the EGL display lacks EGL_KHR_surfaceless_context");
  if (!hasWord(ext, "EGL_KHR_no_config_context"))
    fail("cannot render: the EGL display lacks EGL_KHR_no_config_context");
  display = d;
  return display;
}

}  // namespace

std::unique_ptr<EglContext> EglContext::create(GlApi api) {
  EGLDisplay d = surfacelessDisplay();
  bool es = api == GlApi::Es32;
  if (!eglBindAPI(es ? EGL_OPENGL_ES_API : EGL_OPENGL_API))
    fail(std::string("cannot render: EGL cannot bind the ") + (es ? "OpenGL ES" : "desktop OpenGL") + " API (" +
         eglErrorName(eglGetError()) + ")");
  std::vector<EGLint> attribs;
  if (es) {
    attribs = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 2, EGL_NONE};
  } else {
    attribs = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
               EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  }
  EGLContext ctx = eglCreateContext(d, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs.data());
  if (ctx == EGL_NO_CONTEXT)
    fail(std::string("cannot render: no ") + apiName(api) + " context on the EGL surfaceless display (" +
         eglErrorName(eglGetError()) + ")");
  std::unique_ptr<EglContext> c(new EglContext(api));
  c->display_ = d;
  c->context_ = ctx;
  c->makeCurrent();
  return c;
}

EglContext::~EglContext() {
  if (!context_) return;
  auto d = static_cast<EGLDisplay>(display_);
  if (eglGetCurrentContext() == static_cast<EGLContext>(context_))
    eglMakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(d, static_cast<EGLContext>(context_));
}

void EglContext::makeCurrent() {
  if (!eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE,
                      static_cast<EGLContext>(context_)))
    fail(std::string("cannot render: eglMakeCurrent failed for the ") + apiName(api()) + " context (" +
         eglErrorName(eglGetError()) + ")");
}

}  // namespace wg::rt
