#pragma once
// The wgsl target within a compile: GRAPH.wgsl from a plan without tessellation (WGSL has
// no tessellation stages; the mesh is drawn as it is, as es300 does), the manifest's "wgsl"
// target, and a refusal as a diagnostic at the node whose GLSL has no WGSL form. The WGSL is
// checked by naga and Tint outside the compiler (codegen/wgsl_check.h), since both run in
// JavaScript.
#include <string>
#include <vector>

#include "codegen/compile.h"
#include "codegen/emit_wgsl.h"

namespace wg {

// Adds "<base>.wgsl" to result.files and the wgsl target to result.manifest (whose interface
// was built from the GLSL plans: the WGSL plan's must be the same). False, with an error
// (WG045), when the graph cannot be written as WGSL. `lineOp`, when given, receives the
// module's line -> op map for mapping a validator's messages back to nodes.
bool addWgslTarget(const Program& program, const std::string& base, const std::string& sourceName,
                   CompileResult& result, Diagnostics& diags, std::vector<int>* lineOp = nullptr);

// A validator's message about line `line` (1-based) of a module as a diagnostic (`code`) at
// the node whose op wrote that line, or at the graph file.
void reportWgslMessage(const Program& program, const std::vector<int>& lineOp, int line, const std::string& text,
                       DiagCode code, Diagnostics& diags);

}  // namespace wg
