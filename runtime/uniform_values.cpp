#include "runtime/uniform_values.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/type_ptr.hpp>

namespace wg::rt {

std::vector<float> builtinUniformValue(BuiltinUniform builtin, double angularFrequency, const FrameValues& f) {
  std::vector<float> v;
  auto mat = [&](const glm::mat4& m4) { v.assign(glm::value_ptr(m4), glm::value_ptr(m4) + 16); };
  switch (builtin) {
    case BuiltinUniform::Model: mat(glm::mat4(1.0f)); break;
    case BuiltinUniform::ViewProjection: mat(f.viewProjection); break;
    case BuiltinUniform::View: mat(f.view); break;
    case BuiltinUniform::Projection: mat(f.projection); break;
    case BuiltinUniform::CameraPosition: v = {f.camera.position.x, f.camera.position.y, f.camera.position.z}; break;
    case BuiltinUniform::Time: v = {static_cast<float>(f.time)}; break;
    case BuiltinUniform::ViewportSize: v = {static_cast<float>(f.width), static_cast<float>(f.height)}; break;
    case BuiltinUniform::CameraNearFar: {
      // Each plane clamped into [1e-6, 1e30] (NaN to 1e-6; an infinite far plane to
      // 1e30): the generated shader relies on it (builtinFact(CameraNearFar)).
      auto plane = [](float x) { return !(x >= 1e-6f) ? 1e-6f : std::min(x, 1e30f); };
      v = {plane(f.camera.nearPlane), plane(f.camera.farPlane)};
      break;
    }
    case BuiltinUniform::SunDirection: v = {f.sun.x, f.sun.y, f.sun.z}; break;
    case BuiltinUniform::TimePhase: {
      // mod(omega * time, 2 pi) in double, so phases stay exact at large times.
      double twoPi = 6.283185307179586;
      double phase = angularFrequency * static_cast<double>(f.time);
      phase -= twoPi * std::floor(phase / twoPi);
      v = {static_cast<float>(phase)};
      break;
    }
    case BuiltinUniform::ProbeUv:
    case BuiltinUniform::ProbeWorldPosition:
    case BuiltinUniform::ProbeNormal:
    case BuiltinUniform::ProbeViewDirection:
    case BuiltinUniform::ProbeScreenUv:
    case BuiltinUniform::ProbeFragDepth:
    case BuiltinUniform::ProbeUvGradient:
    case BuiltinUniform::ProbePixel: break;  // refused when the manifest is read
  }
  return v;
}

void clampIntoRange(std::vector<float>& value, float lo, float hi) {
  for (float& x : value) x = clampedIntoRange(x, lo, hi);
}

}  // namespace wg::rt
