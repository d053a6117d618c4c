#pragma once
// The vk450 half of tests/runtime/query_gpu_test.cpp: the graph's vertex stage, as the
// compiler's own SPIR-V (the .vk450.vert.spv `compile` writes, unchanged), run on Vulkan
// (lavapipe) for a list of undisplaced water points, and the displaced position each one
// gets read back.
#include <map>
#include <string>
#include <vector>

#include "codegen/manifest.h"

namespace wg::rt {

struct VkCapturedPoints {
  std::vector<float> positions;  // 3 per point: the vertex stage's v_world_position
  std::string error;             // why nothing was captured; empty on success
};

// Draws point k of `points` (x0, 0, z0) into pixel k of a one-row RGBA32F target, with the
// viewport and scissor that one pixel; a small capture fragment shader (flat input, so the
// vertex's value is copied, never interpolated) writes the world position the vertex stage
// passes on. The block is written as the Vulkan runtime writes it (std140, manifest order;
// parameters at `host`'s value, by name, or their default, clamped into range by the
// runtime's clampIntoRange; builtins for time t) except the
// view-projection, which shrinks every point to the middle of its pixel: a transform
// feedback capture would need Xfb decorations the compiled SPIR-V does not carry.
// The pipeline draws a point list; the vertex stage writes no gl_PointSize (the runtime
// draws triangles), which leaves the point's size to the driver (lavapipe: 1 pixel), so the
// validation layer, which would report exactly that, is off here.
VkCapturedPoints captureVulkanVertexStage(const std::vector<uint32_t>& vertexSpirv, const Manifest& manifest,
                                          const std::vector<std::pair<double, double>>& points, double t,
                                          const std::map<std::string, std::vector<double>>& host);

}  // namespace wg::rt
