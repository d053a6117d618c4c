// The water shaders' uniforms (runtime/water_uniforms.h).
#include "runtime/water_uniforms.h"

#include "runtime/runtime_error.h"

namespace wg::rt {

void WaterUniforms::setup(const Manifest& manifest, const std::vector<GLuint>& programs, const FrameValues& frame) {
  for (const ManifestUniform& m : manifest.uniforms) {
    WaterUniform u;
    u.name = m.name;
    u.type = m.type;
    if (isSampler(u.type))
      manifestError("uniform " + u.name + " has a type the runtime cannot set: " + std::string(typeName(u.type)));
    if (m.parameter) {
      u.parameter = m.parameter->name;
      u.value.assign(m.parameter->defaultValue.begin(), m.parameter->defaultValue.end());
      if (m.parameter->min) u.lo = static_cast<float>(*m.parameter->min);
      if (m.parameter->max) u.hi = static_cast<float>(*m.parameter->max);
      clampIntoRange(u.value, u.lo, u.hi);
    } else {
      u.builtin = m.builtin;
      u.angularFrequency = m.angularFrequency;
      // The runtime provides a builtin when it has a value for it (not the probe's per-case ones).
      if (builtinValue(u, frame).empty())
        manifestError("uniform " + u.name + " asks for builtin '" + std::string(builtinUniformRow(u.builtin).meaning) +
                      "', which the runtime does not provide");
    }
    for (GLuint program : programs) {
      GLint loc = glGetUniformLocation(program, u.name.c_str());
      if (loc >= 0) u.locations.emplace_back(program, loc);  // else optimised out by the driver
    }
    uniforms_.push_back(std::move(u));
  }
  // Errors now, not at the first frame.
  apply(frame);
}

void WaterUniforms::apply(const FrameValues& frame) const {
  for (const auto& u : uniforms_) set(u, u.parameter.empty() ? builtinValue(u, frame) : u.value);
}

bool WaterUniforms::setParameter(const std::string& parameter, const std::vector<float>& value) {
  bool found = false;
  for (auto& u : uniforms_) {
    if (u.parameter != parameter) continue;
    if (value.size() != u.value.size()) return false;
    u.value = value;
    clampIntoRange(u.value, u.lo, u.hi);
    found = true;
  }
  return found;
}

std::vector<float> WaterUniforms::builtinValue(const WaterUniform& u, const FrameValues& frame) const {
  return builtinUniformValue(u.builtin, u.angularFrequency, frame);
}

void WaterUniforms::set(const WaterUniform& u, const std::vector<float>& v) const {
  if (!u.locations.empty() && v.size() != static_cast<size_t>(componentCount(u.type)))
    manifestError("uniform " + u.name + " of type " + std::string(typeName(u.type)) + " got " + std::to_string(v.size()) +
                  " value(s)");
  for (auto [program, loc] : u.locations) {
    glUseProgram(program);
    switch (u.type) {
      case Type::Float: glUniform1f(loc, v[0]); break;
      case Type::Vec2: glUniform2fv(loc, 1, v.data()); break;
      case Type::Vec3: glUniform3fv(loc, 1, v.data()); break;
      case Type::Vec4: glUniform4fv(loc, 1, v.data()); break;
      case Type::Int:
      case Type::Bool: glUniform1i(loc, static_cast<GLint>(v[0])); break;
      case Type::Mat3: glUniformMatrix3fv(loc, 1, GL_FALSE, v.data()); break;
      case Type::Mat4: glUniformMatrix4fv(loc, 1, GL_FALSE, v.data()); break;
      default: break;  // refused when the manifest is read
    }
  }
}

}  // namespace wg::rt
