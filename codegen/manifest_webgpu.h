#pragma once
// The manifest's "webgpu" section (written when the wgsl target was compiled): the bind
// group layout of GRAPH.wgsl (the uniform buffer's members with WGSL offsets and its size;
// each texture's texture and sampler bindings), vertex input locations and formats, varying
// locations, and the clip-space, winding and row-order conventions the module assumes.
// Derived from the interface alone, by the same functions the emitter lays the module out
// with (codegen/emit_wgsl.h), so the two cannot disagree; a manifest read back must carry
// exactly what the compiler would write.
#include "codegen/manifest.h"
#include "core/json_text_writer.h"

namespace wg {

bool writesWebgpuSection(const Manifest& m);
void writeWebgpuSection(JsonTextWriter& w, const Manifest& m);

}  // namespace wg
