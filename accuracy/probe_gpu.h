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

// The value uniform `u` of a probe shader takes for case `c`, drawn into pixel `index` (up
// to 1024 a row): a parameter's (the case's, else the default), the case's builtin, or the
// pixel's centre for u_probe_pixel. Every executor (GL here, Vulkan in vk_probe.h) sets
// the uniforms from this one function. Throws rt::RuntimeError for a builtin the probe
// cannot set.
Value probeUniformValue(const UniformInfo& u, const Program& program, const ProbeCase& c, size_t index);

// On the current GL context. Throws rt::RuntimeError (Driver: the driver rejected the shader; Manifest: a texture
// cannot be loaded). `what` names the shader in errors.
std::vector<std::array<float, 4>> runProbeOnGpu(const EmitResult& shader, const Program& program,
                                                const std::vector<ProbeCase>& cases, bool es, const std::string& what);

}  // namespace wg::accuracy
