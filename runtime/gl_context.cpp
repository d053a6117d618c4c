#include "runtime/gl_context.h"

#include <epoxy/gl.h>

namespace wg::rt {

const char* apiName(GlApi api) { return api == GlApi::Es32 ? "OpenGL ES 3.2" : "OpenGL 4.5 core"; }

std::string GlContext::renderer() const {
  auto s = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return s ? s : "";
}

std::string GlContext::version() const {
  auto s = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return s ? s : "";
}

bool GlContext::hasExtension(const char* name) const { return epoxy_has_gl_extension(name); }

}  // namespace wg::rt
