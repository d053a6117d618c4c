#include "runtime/gl_resources.h"

#include <cstdio>

#include "runtime/runtime_error.h"

namespace wg::rt {
namespace detail {
void deleteShader(GLuint id) { glDeleteShader(id); }
void deleteProgram(GLuint id) { glDeleteProgram(id); }
void deleteBuffer(GLuint id) { glDeleteBuffers(1, &id); }
void deleteVertexArray(GLuint id) { glDeleteVertexArrays(1, &id); }
void deleteTexture(GLuint id) { glDeleteTextures(1, &id); }
void deleteFramebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
}  // namespace detail

Buffer makeBuffer() {
  GLuint id = 0;
  glGenBuffers(1, &id);
  return Buffer(id);
}
VertexArray makeVertexArray() {
  GLuint id = 0;
  glGenVertexArrays(1, &id);
  return VertexArray(id);
}
Texture makeTexture() {
  GLuint id = 0;
  glGenTextures(1, &id);
  return Texture(id);
}

Framebuffer makeFramebuffer() {
  GLuint id = 0;
  glGenFramebuffers(1, &id);
  return Framebuffer(id);
}

namespace {

std::string rendererName() {
  auto s = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  std::string r = s ? s : "unknown";
  size_t paren = r.find(" (");
  return paren == std::string::npos ? r : r.substr(0, paren);
}

std::string trimLog(std::string log) {
  while (!log.empty() && (log.back() == '\n' || log.back() == ' ' || log.back() == '\0')) log.pop_back();
  return log;
}

}  // namespace

Program linkProgram(const std::vector<ShaderSource>& sources, const std::string& what) {
  std::vector<Shader> shaders;
  for (const auto& src : sources) {
    Shader sh(glCreateShader(src.stage));
    const char* text = src.text.c_str();
    GLint len = static_cast<GLint>(src.text.size());
    glShaderSource(sh.id(), 1, &text, &len);
    glCompileShader(sh.id());
    GLint ok = 0;
    glGetShaderiv(sh.id(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
      GLint n = 0;
      glGetShaderiv(sh.id(), GL_INFO_LOG_LENGTH, &n);
      std::string log(static_cast<size_t>(n > 0 ? n : 1), '\0');
      glGetShaderInfoLog(sh.id(), n, nullptr, log.data());
      throw RuntimeError(RuntimeError::Kind::Driver, "the GL driver (" + rendererName() + ") rejected " + src.name +
                                                         " (" + what + "):\n" + trimLog(log));
    }
    shaders.push_back(std::move(sh));
  }
  Program p(glCreateProgram());
  for (const auto& sh : shaders) glAttachShader(p.id(), sh.id());
  glLinkProgram(p.id());
  GLint ok = 0;
  glGetProgramiv(p.id(), GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint n = 0;
    glGetProgramiv(p.id(), GL_INFO_LOG_LENGTH, &n);
    std::string log(static_cast<size_t>(n > 0 ? n : 1), '\0');
    glGetProgramInfoLog(p.id(), n, nullptr, log.data());
    std::string names;
    for (const auto& s : sources) names += (names.empty() ? "" : " + ") + s.name;
    throw RuntimeError(RuntimeError::Kind::Driver,
                       "the GL driver (" + rendererName() + ") could not link " + names + " (" + what + "):\n" + trimLog(log));
  }
  for (const auto& sh : shaders) glDetachShader(p.id(), sh.id());
  return p;
}

void checkGl(const char* where) {
  GLenum e = glGetError();
  if (e == GL_NO_ERROR) return;
  char buf[32];
  std::snprintf(buf, sizeof buf, "0x%04x", e);
  throw RuntimeError(RuntimeError::Kind::Driver, std::string("GL error ") + buf + " in " + where);
}

}  // namespace wg::rt
