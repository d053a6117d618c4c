#pragma once
// The manifest of one compile, from the final Program and the shader plans the targets
// were emitted from.
#include <string>

#include "codegen/manifest.h"
#include "codegen/shader_plan.h"
#include "core/program.h"

namespace wg {

// `baseName` names the files: "<baseName>.<target>.<stage>", one per planned stage. The
// interface (attributes, uniforms, varyings, functions, textures) is the same for every
// target and taken from the first target's plan; the manifest lists no preset and no cross
// targets (compileGraph and compileGraphWithCross add them).
Manifest buildManifest(const Program& program, const TargetPlans& plans, const std::string& baseName);

}  // namespace wg
