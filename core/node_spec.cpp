#include "core/node_spec.h"

#include <stdexcept>

#include "core/number_format.h"
#include "core/ocean_settings.h"

namespace wg {

const Value& EvalEnvironment::builtin(Builtin b) const { return this->*builtinRow(b).environment; }

Value EvalEnvironment::sceneAt(SceneSampler s, double u, double v) const {
  if (const SceneImage* image = sceneImages[static_cast<size_t>(s)]) return image->sample(u, v);
  Value EvalEnvironment::*field = sceneSamplerRow(s).environment;
  if (!field) throw std::logic_error("the reference reads the water G-buffer as builtins, not by look-up");
  return this->*field;
}

int portIndex(const std::vector<PortSpec>& ports, std::string_view name) {
  for (size_t i = 0; i < ports.size(); ++i)
    if (ports[i].name == name) return static_cast<int>(i);
  return -1;
}

int NodeSpec::inputIndex(std::string_view name) const { return portIndex(inputs, name); }
int NodeSpec::outputIndex(std::string_view name) const { return portIndex(outputs, name); }
int NodeSpec::optionIndex(std::string_view name) const {
  for (size_t i = 0; i < options.size(); ++i)
    if (options[i].name == name) return static_cast<int>(i);
  return -1;
}

ValueFact builtinFact(Builtin b) {
  ValueFact f;
  switch (b) {
    case Builtin::Normal:         // b_normal = wg_safe_normalize_vec3(...) in every stage
    case Builtin::ViewDirection:  // b_view_direction = wg_safe_normalize_vec3(camera - p)
      f.normalized = true;
      f.lo = -1;
      f.hi = 1;
      break;
    case Builtin::SunDirection:  // the runtime uploads glm::normalize(...) (runtime/scene.cpp)
      f.normalized = true;
      f.lo = -1;
      f.hi = 1;
      break;
    case Builtin::CameraNearFar:  // runtime and clients clamp each plane into [1e-6, 1e30]
      f.lo = 1e-6;
      f.hi = 1e30;
      break;
    case Builtin::PixelAngle:  // 2 / |projection[1][1] viewport.y|: positive (inf for a degenerate projection)
      f.lo = 0;
      break;
    case Builtin::ScreenUv:   // gl_FragCoord.xy / viewport inside the viewport
    case Builtin::FragDepth:  // gl_FragCoord.z with the default depth range
      f.lo = 0;
      f.hi = 1;
      break;
    default: break;
  }
  return f;
}

const Value& EvalContext::input(std::string_view port) const {
  int i = spec().inputIndex(port);
  if (i < 0) throw std::logic_error("node '" + spec().type + "' has no input '" + std::string(port) + "'");
  return input(i);
}

}  // namespace wg
