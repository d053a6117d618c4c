#pragma once
// Our shader stages as glslang's languages; shared by validation and the HLSL round trip.
#include <glslang/Public/ShaderLang.h>

#include "codegen/target.h"

namespace wg {

inline EShLanguage glslangStage(ShaderStage s) {
  switch (s) {
    case ShaderStage::Vertex: return EShLangVertex;
    case ShaderStage::TessControl: return EShLangTessControl;
    case ShaderStage::TessEvaluation: return EShLangTessEvaluation;
    case ShaderStage::Fragment: return EShLangFragment;
  }
  return EShLangVertex;
}

}  // namespace wg
