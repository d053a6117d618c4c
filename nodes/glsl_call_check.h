#pragma once
// Registration check: every GLSL library function a node's emit can call exists in the
// library (nodes/glsl/), so a misspelt or removed function fails when the node is
// registered, not when some option combination is first compiled.
#include "core/node_spec.h"
#include "nodes/glsl_library.h"

namespace wg {

// Runs `spec.emit` over the defaults, each choice of each Enum and Bool option, each hard
// case's options, each port type its Gen and Custom ports admit, with no facts and with
// facts that enable the fact-specialised variants; throws std::logic_error naming the node
// and the first wg_* name the library lacks.
void checkGlslCalls(const NodeSpec& spec, const GlslLibrary& library);

}  // namespace wg
