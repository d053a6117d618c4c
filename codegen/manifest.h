#pragma once
// The manifest beside the shaders: what a runtime or engine needs to drive them
// (attributes, uniforms with defaults and ranges, varyings, scene resources, render
// passes) and what the compiler kept and removed, so a user can see what each choice costs.
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "codegen/emit_glsl.h"
#include "core/program.h"

namespace wg {

inline constexpr int kManifestFormat = 1;

nlohmann::json buildManifest(const Program& program, const std::vector<std::pair<Target, EmitResult>>& emitted,
                             const std::string& baseName);

}  // namespace wg
