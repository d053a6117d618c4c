#pragma once
// `check --target wgsl`'s frames: one compiled graph's water (its WGSL module, or one of its
// read-back tap modules) drawn in the built-in scene by the WebGPU runner
// (clients/webgpu/watergraph-webgpu.js, through watergraph-webgpu-check.js) in the helper's
// headless Chromium, into an RGBA32F frame read back exactly. Everything that depends on the
// view is computed here as the runtime computes it and handed over: the pass plan
// (runtime/pass_plan.h, every target RGBA32F), the water grid, the camera's GL matrices, the
// sun, and the uniform buffer's bytes at the module's WGSL offsets (runtime/uniform_values.h).
#include <memory>

#include "accuracy/gpu_executor.h"
#include "accuracy/webgpu_session.h"

namespace wg::accuracy {

// `module`: the WGSL text (a ShaderSource of stage GL_FRAGMENT_SHADER holding both entry
// points). A spectral ocean is simulated in the page from the compile's ocean module. Throws
// rt::RuntimeError: Kind::Manifest for what the runner cannot draw (a mipmapped node texture),
// rt::TextureLoadError for a node texture that does not load, Kind::Driver for Tint's or
// WebGPU's errors.
std::unique_ptr<WaterFrames> makeWgslWaterFrames(WebgpuSession& session, const CompileResult& result,
                                                 const rt::ShaderSource& module, const rt::RenderSettings& settings);

}  // namespace wg::accuracy
