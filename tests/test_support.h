#pragma once
// Helpers shared by the test suites: paths into the source tree, reading files, running
// the watergraph binary.
#include <string>

namespace wg::test {

std::string sourceDir();                     // the repository root
std::string sourcePath(const std::string& rel);
std::string readFile(const std::string& path);
std::string watergraphBinary();              // build/bin/watergraph
// Runs a shell command; returns its exit status and fills `output` with stdout+stderr.
int runCommand(const std::string& command, std::string* output);
// A fresh empty directory under the system temp folder, removed by the caller.
std::string makeTempDir(const std::string& prefix);

}  // namespace wg::test
