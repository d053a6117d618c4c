#pragma once
// The manifest's "vulkan" section (written when vk450 was compiled): the descriptor set
// and binding of every resource, the uniform block's std140 offsets and size, vertex input
// locations and formats, varying locations, push constants (none) and the clip-space,
// depth-range, winding and row-order conventions the shaders assume.
#include "codegen/manifest.h"
#include "core/json_text_writer.h"

namespace wg {

bool writesVulkanSection(const Manifest& m);
void writeVulkanSection(JsonTextWriter& w, const Manifest& m);

// The "varyings" (location by order) and "vertex_inputs" members both API sections share,
// each vertex input's format named by `format` (the API's name for a float vector type).
void writeVertexInterface(JsonTextWriter& w, const Manifest& m, const char* (*format)(Type));

}  // namespace wg
