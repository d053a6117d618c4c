#include "accuracy/probe_gpu.h"

#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>

#include "core/ocean_settings.h"
#include "nodes/texture_source.h"
#include "runtime/gl_resources.h"
#include "runtime/node_texture.h"
#include "runtime/ocean_simulation.h"
#include "runtime/runtime_error.h"

namespace wg::accuracy {
namespace {

using rt::RuntimeError;

std::string fullscreenVertex(bool es) {
  return std::string(es ? "#version 300 es\nprecision highp float;\n" : "#version 330 core\n") +
         "void main() {\n"
         "  vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);\n"
         "  gl_Position = vec4(p, 0.0, 1.0);\n"
         "}\n";
}

// The value a builtin uniform has in a case.
Value builtinValue(const UniformInfo& u, const EvalEnvironment& env) {
  const BuiltinUniformRow& row = builtinUniformRow(u.builtin);
  if (row.carries) return env.builtin(*row.carries);
  switch (u.builtin) {
    case BuiltinUniform::ViewportSize: return Value::vector({1, 1});
    case BuiltinUniform::ProbeUvGradient: return Value::vector({env.uvDx[0], env.uvDx[1], env.uvDy[0], env.uvDy[1]});
    case BuiltinUniform::TimePhase: {
      // As the runtime does: mod(omega * t, 2 pi) in double (the eval does the same).
      double phase = u.omega * env.time[0];
      phase -= 6.283185307179586 * std::floor(phase / 6.283185307179586);
      return Value::scalar(phase);
    }
    default: break;
  }
  throw RuntimeError(RuntimeError::Kind::Manifest,
                     "the probe cannot set builtin uniform " + u.name + " ('" + std::string(row.meaning) + "')");
}

void setUniform(GLint loc, Type type, const Value& v) {
  float f[16];
  for (int i = 0; i < 16; ++i) f[i] = static_cast<float>(v.c[static_cast<size_t>(i)]);
  switch (type) {
    case Type::Float: glUniform1f(loc, f[0]); break;
    case Type::Vec2: glUniform2fv(loc, 1, f); break;
    case Type::Vec3: glUniform3fv(loc, 1, f); break;
    case Type::Vec4: glUniform4fv(loc, 1, f); break;
    case Type::Mat3: glUniformMatrix3fv(loc, 1, GL_FALSE, f); break;
    case Type::Mat4: glUniformMatrix4fv(loc, 1, GL_FALSE, f); break;
    default: throw RuntimeError(RuntimeError::Kind::Manifest, "the probe cannot set a uniform of this type");
  }
}

rt::Texture makeNodeTexture(const TextureInfo& t, const std::string& graphDir) {
  std::string why;
  auto img = loadTexture(t.source, graphDir, &why);
  if (!img || img->width <= 0 || img->height <= 0)
    throw RuntimeError(RuntimeError::Kind::Manifest, "texture '" + t.source + "' cannot be loaded: " + why);
  return rt::makeNodeTexture(img->width, img->height, img->rgba.data(), t.sampler);
}

// A 1x1 RGBA32F texture (six faces for a cube), nearest: every fetch returns the texel.
rt::Texture makeSceneTexture(bool cube) {
  rt::Texture tex = rt::makeTexture();
  GLenum target = cube ? GLenum(GL_TEXTURE_CUBE_MAP) : GLenum(GL_TEXTURE_2D);
  glBindTexture(target, tex.id());
  glTexStorage2D(target, 1, GL_RGBA32F, 1, 1);
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_REPEAT);
  return tex;
}

void fillSceneTexture(GLuint tex, bool cube, const std::array<float, 4>& texel) {
  if (cube) {
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex);
    for (int face = 0; face < 6; ++face)
      glTexSubImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + static_cast<GLenum>(face), 0, 0, 0, 1, 1, GL_RGBA, GL_FLOAT, texel.data());
  } else {
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_FLOAT, texel.data());
  }
}

}  // namespace

Value probeUniformValue(const UniformInfo& u, const Program& program, const ProbeCase& c, size_t index) {
  if (u.parameter >= 0) {
    const ProgramParameter& p = program.parameters[static_cast<size_t>(u.parameter)];
    Value v = p.defaultValue;
    for (const auto& [name, value] : c.parameters)
      if (name == p.name) v = value.convertedTo(p.type);
    return v;
  }
  if (u.builtin == BuiltinUniform::ProbePixel)  // gl_FragCoord at the centre of the case's pixel
    return Value::vector({static_cast<double>(index % 1024) + 0.5, static_cast<double>(index / 1024) + 0.5});
  return builtinValue(u, c.env);
}

std::vector<std::array<float, 4>> runProbeOnGpu(const EmitResult& shader, const Program& program,
                                                const std::vector<ProbeCase>& cases, bool es, const std::string& what) {
  if (cases.empty()) return {};
  const EmittedShader* frag = nullptr;
  for (const auto& s : shader.shaders)
    if (s.stage == ShaderStage::Fragment) frag = &s;
  if (!frag) throw RuntimeError(RuntimeError::Kind::Manifest, what + ": no fragment shader to probe");
  rt::Program prog = rt::linkProgram({{GL_VERTEX_SHADER, "probe fullscreen.vert", fullscreenVertex(es)},
                                      {GL_FRAGMENT_SHADER, what, frag->text}},
                                     what);
  glUseProgram(prog.id());

  // The target: up to 1024 cases per row.
  const int width = static_cast<int>(std::min<size_t>(cases.size(), 1024));
  const int height = static_cast<int>((cases.size() + 1023) / 1024);
  rt::Texture color = rt::makeTexture();
  glBindTexture(GL_TEXTURE_2D, color.id());
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, width, height);
  rt::Framebuffer fbo = rt::makeFramebuffer();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color.id(), 0);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw RuntimeError(RuntimeError::Kind::Driver, "the RGBA32F probe target is incomplete on this driver");
  const float clear[4] = {0, 0, 0, 0};
  glClearBufferfv(GL_COLOR, 0, clear);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  rt::VertexArray vao = rt::makeVertexArray();
  glBindVertexArray(vao.id());

  // Samplers: one unit each, in the shader's order.
  struct Bound {
    const TextureInfo* info;
    rt::Texture texture;
    GLenum target;
  };
  std::vector<Bound> bound;
  // The ocean maps come from the simulation, run at each case's time (runtime/ocean_simulation.h).
  std::unique_ptr<rt::OceanSimulation> oceans;
  if (!shader.oceans.empty())
    oceans = std::make_unique<rt::OceanSimulation>(shader.oceans, shader.textures, es ? rt::SceneShaderApi::Es300 : rt::SceneShaderApi::Gl330);
  for (const auto& t : shader.textures) {
    bool cube = t.type == Type::SamplerCube;
    Bound b{&t, t.scene || t.ocean ? makeSceneTexture(cube) : makeNodeTexture(t, program.directory),
            cube ? GLenum(GL_TEXTURE_CUBE_MAP) : GLenum(GL_TEXTURE_2D)};
    GLint loc = glGetUniformLocation(prog.id(), t.name.c_str());
    if (loc >= 0) glUniform1i(loc, static_cast<GLint>(bound.size()));
    bound.push_back(std::move(b));
  }
  std::vector<GLint> locations;
  for (const auto& u : shader.uniforms) locations.push_back(glGetUniformLocation(prog.id(), u.name.c_str()));
  rt::checkGl("setting up the probe");

  std::optional<std::uint32_t> oceanTime;  // the loop fraction the maps hold
  for (size_t i = 0; i < cases.size(); ++i) {
    const ProbeCase& c = cases[i];
    if (oceans && oceanTime != ocean::loopFraction(c.env.time[0])) {
      oceans->update(c.env.time[0]);
      oceanTime = ocean::loopFraction(c.env.time[0]);
      glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
      glUseProgram(prog.id());
      glBindVertexArray(vao.id());
    }
    for (size_t k = 0; k < shader.uniforms.size(); ++k) {
      const UniformInfo& u = shader.uniforms[k];
      if (locations[k] < 0) continue;  // optimised out by the driver
      setUniform(locations[k], u.type, probeUniformValue(u, program, c, i));
    }
    for (size_t k = 0; k < bound.size(); ++k) {
      glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(k));
      glBindTexture(bound[k].target, bound[k].info->ocean ? oceans->map(*bound[k].info->ocean) : bound[k].texture.id());
      if (bound[k].info->scene)
        fillSceneTexture(bound[k].texture.id(), bound[k].target == GL_TEXTURE_CUBE_MAP,
                         sceneSamplerRow(*bound[k].info->scene).caseTexel(c.env));
    }
    glViewport(static_cast<GLint>(i % 1024), static_cast<GLint>(i / 1024), 1, 1);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  rt::checkGl("drawing the probe cases");
  std::vector<float> pixels(static_cast<size_t>(width) * static_cast<size_t>(height) * 4);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, pixels.data());
  rt::checkGl("reading the probe target");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  std::vector<std::array<float, 4>> out(cases.size());
  for (size_t i = 0; i < cases.size(); ++i)
    for (int ch = 0; ch < 4; ++ch) out[i][static_cast<size_t>(ch)] = pixels[i * 4 + static_cast<size_t>(ch)];
  return out;
}

}  // namespace wg::accuracy
