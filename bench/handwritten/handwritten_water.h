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

#include "codegen/compile.h"
#include "codegen/glslang_validate.h"
#include "codegen/target.h"
#include "runtime/preview.h"

namespace wg::handwritten {

// The example graphs that have a hand-written counterpart: the classic WebGL water renderer
// and the stylized water shader.
inline const std::vector<std::string>& graphs() {
  static const std::vector<std::string> names = {"classic_webgl", "stylized"};
  return names;
}

// The glsl330 files of a manifest, in pipeline order.
inline const std::vector<ManifestStageFile>& glsl330Files(const Manifest& manifest) {
  const ManifestTarget* target = manifest.target(targetName(Target::Glsl330));
  if (!target) throw std::runtime_error("the graph was not compiled for glsl330");
  return target->files;
}

// The generated glsl330 shaders of a compile, in pipeline order.
inline std::vector<ShaderSource> generatedShaders(const CompileResult& result) {
  std::vector<ShaderSource> out;
  for (const ManifestStageFile& f : glsl330Files(result.manifest)) {
    auto it = std::find_if(result.files.begin(), result.files.end(), [&](const OutputFile& o) { return o.name == f.file; });
    if (it == result.files.end()) throw std::runtime_error("the manifest names " + f.file + " but the compile has no such file");
    out.push_back({f.stage, f.file, it->contents});
  }
  return out;
}

// bench/handwritten/<graph>.glsl330.<stage> for every stage the generated manifest has.
// Throws std::runtime_error naming the file when one is missing.
inline std::vector<ShaderSource> handwrittenShaders(const std::string& sourceDir, const std::string& graph,
                                                    const Manifest& manifest) {
  std::vector<ShaderSource> out;
  for (const ManifestStageFile& f : glsl330Files(manifest)) {
    std::string path = sourceDir + "/bench/handwritten/" + graph + ".glsl330." + std::string(stageExtension(f.stage));
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot read the hand-written shader");
    std::ostringstream text;
    text << in.rdbuf();
    out.push_back({f.stage, path, text.str()});
  }
  return out;
}

// For the GL runtime.
inline std::vector<rt::ShaderSource> forRuntime(const std::vector<ShaderSource>& shaders) {
  std::vector<rt::ShaderSource> out;
  for (const auto& s : shaders) out.push_back({rt::glShaderStage(s.stage), s.fileName, s.text});
  return out;
}

}  // namespace wg::handwritten
