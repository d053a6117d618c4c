#pragma once
// The hand-written water shaders of bench/handwritten/ beside the generated ones of the
// matching example graph (graphs/<graph>.json): the same stages, read in the order the
// generated manifest names them, so both run through one Renderer setup with the same
// manifest (uniforms, textures, passes). Used by wg_bench_handwritten and the runtime test
// that keeps the hand-written shaders compiling and matching the generated image.
#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <epoxy/gl.h>
#include <nlohmann/json.hpp>

#include "codegen/compile.h"
#include "codegen/glslang_validate.h"
#include "codegen/target.h"
#include "runtime/gl_resources.h"

namespace wg::handwritten {

// The example graphs that have a hand-written counterpart: seed 000 and seed 003.
inline const std::vector<std::string>& graphs() {
  static const std::vector<std::string> names = {"classic_webgl", "stylized"};
  return names;
}

inline constexpr ShaderStage kStages[] = {ShaderStage::Vertex, ShaderStage::TessControl, ShaderStage::TessEvaluation,
                                          ShaderStage::Fragment};

// The generated glsl330 shaders of a compile, in pipeline order.
inline std::vector<ShaderSource> generatedShaders(const CompileResult& result) {
  const auto& files = result.manifest.at("targets").at("glsl330");
  std::vector<ShaderSource> out;
  for (ShaderStage s : kStages) {
    std::string ext(stageExtension(s));
    if (!files.contains(ext)) continue;
    std::string name = files.at(ext).get<std::string>();
    auto it = std::find_if(result.files.begin(), result.files.end(), [&](const OutputFile& f) { return f.name == name; });
    if (it == result.files.end()) throw std::runtime_error("the manifest names " + name + " but the compile has no such file");
    out.push_back({s, name, it->contents});
  }
  return out;
}

// bench/handwritten/<graph>.glsl330.<stage> for every stage the generated manifest has.
// Throws std::runtime_error naming the file when one is missing.
inline std::vector<ShaderSource> handwrittenShaders(const std::string& sourceDir, const std::string& graph,
                                                    const nlohmann::json& manifest) {
  const auto& files = manifest.at("targets").at("glsl330");
  std::vector<ShaderSource> out;
  for (ShaderStage s : kStages) {
    std::string ext(stageExtension(s));
    if (!files.contains(ext)) continue;
    std::string path = sourceDir + "/bench/handwritten/" + graph + ".glsl330." + ext;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot read the hand-written shader");
    std::ostringstream text;
    text << in.rdbuf();
    out.push_back({s, path, text.str()});
  }
  return out;
}

// For the GL runtime.
inline std::vector<rt::ShaderSource> forRuntime(const std::vector<ShaderSource>& shaders) {
  std::vector<rt::ShaderSource> out;
  for (const auto& s : shaders) {
    GLenum stage = s.stage == ShaderStage::Vertex           ? GL_VERTEX_SHADER
                   : s.stage == ShaderStage::TessControl    ? GL_TESS_CONTROL_SHADER
                   : s.stage == ShaderStage::TessEvaluation ? GL_TESS_EVALUATION_SHADER
                                                            : GL_FRAGMENT_SHADER;
    out.push_back({stage, s.fileName, s.text});
  }
  return out;
}

}  // namespace wg::handwritten
