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

int EmitContext::inputIndex(std::string_view port) const {
  int i = spec().inputIndex(port);
  if (i < 0) throw std::logic_error("node '" + spec().type + "' has no input '" + std::string(port) + "'");
  return i;
}

std::string EmitContext::input(std::string_view port) { return input(inputIndex(port)); }

std::string EmitContext::sceneTexture(std::string_view resource) {
  auto r = parseSceneResource(resource);
  if (!r) throw std::logic_error("node '" + spec().type + "' samples unknown scene resource '" + std::string(resource) + "'");
  return sceneTexture(*r);
}

std::string EmitContext::sampleTexture(std::string_view option, const SamplerState& sampler, const std::string& coord) {
  return "texture(" + texture(option, sampler) + ", " + coord + ")";
}

std::string EmitContext::sampleScene(SceneResource resource, const std::string& coord) {
  return "texture(" + sceneTexture(resource) + ", " + coord + ")";
}

std::string EmitContext::sampleScene(std::string_view resource, const std::string& coord) {
  auto r = parseSceneResource(resource);
  if (!r) throw std::logic_error("node '" + spec().type + "' samples unknown scene resource '" + std::string(resource) + "'");
  return sampleScene(*r, coord);
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
    case Builtin::ScreenUv:   // gl_FragCoord.xy / viewport inside the viewport
    case Builtin::FragDepth:  // gl_FragCoord.z with the default depth range
      f.lo = 0;
      f.hi = 1;
      break;
    default: break;
  }
  return f;
}

ValueFact EmitContext::inputFact(int) const { return {}; }
const ocean::OceanSettings& EmitContext::oceanSettings(int) const {
  static const ocean::OceanSettings defaults;
  return defaults;
}
std::string EmitContext::oceanMap(int, int, int) {
  throw std::logic_error("node '" + spec().type + "' reads an ocean map where no planner gives one");
}
ValueFact EmitContext::knownBuiltin(Builtin) const { return {}; }
std::optional<Value> EmitContext::inputConstant(int) const { return std::nullopt; }
ValueFact EmitContext::inputFact(std::string_view port) const { return inputFact(inputIndex(port)); }

std::string EmitContext::literal(double x) const { return formatGlslFloat(x); }

std::string EmitContext::literal(const Value& v) const {
  if (v.size() == 1) return formatGlslFloat(v[0]);
  std::string s(typeName(v.type));
  s += '(';
  for (int i = 0; i < v.size(); ++i) {
    if (i) s += ", ";
    s += formatGlslFloat(v[i]);
  }
  return s + ')';
}

std::string EmitContext::call(std::string_view fn, std::initializer_list<std::string> args) {
  std::string s(fn);
  s += '(';
  bool first = true;
  for (const auto& a : args) {
    if (!first) s += ", ";
    s += a;
    first = false;
  }
  return s + ')';
}

const Value& EvalContext::input(std::string_view port) const {
  int i = spec().inputIndex(port);
  if (i < 0) throw std::logic_error("node '" + spec().type + "' has no input '" + std::string(port) + "'");
  return input(i);
}

}  // namespace wg
