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

// The render passes a program needs: the water surface, plus one per scene resource its
// nodes read (planned from NodeSpec::resources), in a fixed order.
std::vector<std::string> resourcesOf(const Program& program);
std::vector<std::string> passesFor(const std::vector<std::string>& resources);

nlohmann::json buildManifest(const Program& program, const std::vector<std::pair<Target, EmitResult>>& emitted,
                             const std::string& baseName);

}  // namespace wg
