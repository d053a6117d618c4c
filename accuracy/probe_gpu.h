#pragma once
// Runs a probe shader (codegen EmitMode::Probe) on the current GL context: one pixel of an
// RGBA32F target per case, drawn by a full-screen triangle restricted to that pixel, with
// the case's builtins, time phases and parameters in the uniforms and the scene textures
// replaced by 1x1 float textures holding the case's values (what any fetch returns, as the
// CPU reference assumes). Node textures are uploaded as the runtime uploads them, with
// their sampler state. The uv builtin varies by the case's gradient across the pixel's
// quad (u_probe_uv_gradient about u_probe_pixel), so a mipmapped look-up picks the
// level the reference picks.
#include <array>
#include <string>
#include <vector>

#include "accuracy/probe_cases.h"
#include "codegen/emit_glsl.h"
#include "core/program.h"

namespace wg::accuracy {

// Throws rt::RuntimeError (Driver: the driver rejected the shader; Manifest: a texture
// cannot be loaded). `what` names the shader in errors.
std::vector<std::array<float, 4>> runProbeOnGpu(const EmitResult& shader, const Program& program,
                                                const std::vector<ProbeCase>& cases, bool es, const std::string& what);

}  // namespace wg::accuracy
