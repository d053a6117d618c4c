#include "codegen/target.h"

namespace wg {

std::string_view targetName(Target t) {
  switch (t) {
    case Target::Glsl330: return "glsl330";
    case Target::Es300: return "es300";
    case Target::Vk450: return "vk450";
  }
  return "?";
}

std::string_view targetGlslVersion(Target t) {
  switch (t) {
    case Target::Glsl330: return "330 core";
    case Target::Es300: return "300 es";
    case Target::Vk450: return "450";
  }
  return "330 core";
}

std::optional<Target> parseTarget(std::string_view name) {
  for (Target t : allTargets())
    if (targetName(t) == name) return t;
  return std::nullopt;
}

const std::vector<Target>& allTargets() {
  static const std::vector<Target> targets = {Target::Glsl330, Target::Es300, Target::Vk450};
  return targets;
}

std::string_view crossTargetName(CrossTarget t) {
  switch (t) {
    case CrossTarget::Msl: return "msl";
    case CrossTarget::Hlsl: return "hlsl";
  }
  return "?";
}

std::optional<CrossTarget> parseCrossTarget(std::string_view name) {
  for (CrossTarget t : allCrossTargets())
    if (crossTargetName(t) == name) return t;
  return std::nullopt;
}

const std::vector<CrossTarget>& allCrossTargets() {
  static const std::vector<CrossTarget> targets = {CrossTarget::Msl, CrossTarget::Hlsl};
  return targets;
}

std::string_view stageExtension(ShaderStage s) {
  switch (s) {
    case ShaderStage::Vertex: return "vert";
    case ShaderStage::TessControl: return "tesc";
    case ShaderStage::TessEvaluation: return "tese";
    case ShaderStage::Fragment: return "frag";
  }
  return "?";
}

}  // namespace wg
