#pragma once
// Writing compiled files so that a failure never leaves a half-written set: every file is
// written to a temporary name in the target folder first, and only when all of them are
// complete are they renamed into place.
#include <string>
#include <vector>

#include "codegen/compile.h"
#include "core/diagnostic.h"

namespace wg {

// Creates `dir` if needed. On any error (WG051) nothing new is left in `dir`.
bool writeOutputFiles(const std::string& dir, const std::vector<OutputFile>& files, Diagnostics& diags);
// One file, same guarantee (used by fmt and the editor's save).
bool writeFileAtomically(const std::string& path, const std::string& contents, Diagnostics& diags);
// Whether writeFileAtomically could write `path` now (its folder exists, or can be made
// under the nearest existing folder, which writeFileAtomically then does; an existing file
// is a regular, writable file); the reason as an error otherwise. For a file written after
// others (a depfile), checked before any of them.
bool checkWritable(const std::string& path, Diagnostics& diags);

}  // namespace wg
