// Nothing the tool decides searches the text of the shaders it generated: check's read-back
// is planned from the ShaderPlan (codegen/readback_taps.h, accuracy/readback.h). This greps
// the sources outside tests for the helpers and searches the text-based read-back used
// (findMain, samplerUse, callEnd, a search for main() or a texture() call), so none comes
// back. The user's own edit of a shader (check --mutate, probe --mutate) is a text edit by
// design and searches for the user's text, not for any of these.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "test_support.h"

namespace wg {
namespace {

const char* const kForbidden[] = {
    "findMain", "samplerUse", "callEnd", ".find(\"void main", ".rfind(\"void main", ".find(\"texture(",
    ".find(std::string(\"texture(", ".find(\"gl_FragColor", ".find(\"fragColor",
};

bool isSource(const std::filesystem::path& p) {
  static const char* const kExtensions[] = {".cpp", ".h", ".hpp", ".c", ".js", ".mjs", ".ts"};
  for (const char* e : kExtensions)
    if (p.extension() == e) return true;
  return false;
}

TEST(SourceTree, NoSearchOfGeneratedShaderText) {
  size_t files = 0;
  for (const char* dir : {"accuracy", "cli", "runtime", "editor", "codegen", "clients", "core", "nodes"}) {
    const std::filesystem::path root = test::sourcePath(dir);
    if (!std::filesystem::exists(root)) continue;
    for (auto it = std::filesystem::recursive_directory_iterator(root); it != std::filesystem::recursive_directory_iterator(); ++it) {
      if (it->is_directory() && it->path().filename() == "node_modules") {
        it.disable_recursion_pending();
        continue;
      }
      if (!it->is_regular_file() || !isSource(it->path())) continue;
      ++files;
      std::ifstream in(it->path(), std::ios::binary);
      std::stringstream text;
      text << in.rdbuf();
      const std::string s = text.str();
      for (const char* pattern : kForbidden)
        EXPECT_EQ(s.find(pattern), std::string::npos) << it->path().string() << " contains " << pattern;
    }
  }
  EXPECT_GT(files, 100u);  // the tree was found
}

}  // namespace
}  // namespace wg
