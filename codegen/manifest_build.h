#pragma once
// The manifest of one compile, from the final Program and what each target's emitter
// returned.
#include <string>
#include <utility>
#include <vector>

#include "codegen/emit_glsl.h"
#include "codegen/manifest.h"
#include "core/program.h"

namespace wg {

// `baseName` names the files: "<baseName>.<target>.<stage>". The interface (attributes,
// uniforms, varyings, functions, textures) is the same for every target and taken from the
// first; the manifest lists no preset and no cross targets (compileGraph and
// compileGraphWithCross add them).
Manifest buildManifest(const Program& program, const std::vector<std::pair<Target, EmitResult>>& emitted,
                       const std::string& baseName);

}  // namespace wg
