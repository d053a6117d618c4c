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
// One file, same guarantee: every file the tool writes goes through here (render -o, the
// depfile, --error-map, --plot, --markdown, --write-preset, fmt, the editor's save ...).
// A symbolic link at `path` is replaced by the new file, never followed.
bool writeFileAtomically(const std::string& path, const std::string& contents, Diagnostics& diags);
// The file an in-place rewrite (fmt, tune --write-preset) replaces: the real file behind
// `path`, so a link the user keeps to a graph stays a link and the graph is formatted;
// `path` itself when it cannot be resolved.
std::string realPathForRewrite(const std::string& path);
// Whether writeFileAtomically could write `path` now (its folder exists, or can be made
// under the nearest existing folder, which writeFileAtomically then does; an existing file
// is a regular, writable file, or a link, which would be replaced); the reason as an error
// (WG051) otherwise. Every command checks its output paths so before doing any work.
bool checkWritable(const std::string& path, Diagnostics& diags);
// The same for an output folder (compile -o): it is a folder we may write into, or can be
// made under its nearest existing folder.
bool checkFolderWritable(const std::string& dir, Diagnostics& diags);

}  // namespace wg
