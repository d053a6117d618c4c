#pragma once
// Shared by the runtime suites: compiling example graphs, hand-made water shaders and
// manifests for pass tests, and the render settings the checked-in images use.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "codegen/compile.h"
#include "runtime/renderer.h"

namespace wg::test {

// graphs/*.json in the source tree, sorted, as base names ("lake").
std::vector<std::string> exampleGraphNames();
// Compiles graphs/<name>.json for `targets` (validated); fails the test on errors.
CompileResult compileExample(const std::string& name, const std::vector<Target>& targets = {Target::Glsl330, Target::Es300});

// The settings of every checked-in preview: 320 x 180, camera above, time 3.5 s.
rt::RenderSettings smallSettings();

// A water shader written by hand that samples the given scene textures (u_reflection, ...)
// at the screen position and sums them with weights; for pass tests.
std::vector<rt::ShaderSource> handWaterShaders(bool es, const std::vector<std::string>& samplers);
// The JSON of a manifest listing `passes` (plus water_surface), the builtins the hand
// shaders use and a texture entry per sampler (Manifest::fromJson reads it, as it would
// a hand-written manifest file).
nlohmann::json handManifest(const std::vector<std::string>& passes, const std::vector<std::string>& samplers);

}  // namespace wg::test
