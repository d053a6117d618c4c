#pragma once
// The property of the function-file fuzz target (fuzz_function_file.cpp), shared with the
// replay of its corpus in the test suite. The fuzz bytes are a GLSL function file: written
// as f.glsl beside a graph whose glsl_function node calls its function `f` (its inputs
// left for the resolver to judge). Whatever the bytes: the compile (every target, glslang
// on) either succeeds, or fails with clear errors (a message, a line:col) of which every
// one placed in f.glsl lies inside the file's lines; and glslang never rejects generated
// code (WG040/WG041): no byte of the file reaches a shader glslang has not accepted.
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

#include "fuzz_properties.h"

namespace wg::fuzz {

inline const char* functionFileGraph() {
  return R"({"version": 1, "name": "fn",
  "nodes": [{"id": "f", "type": "glsl_function", "options": {"file": "f.glsl", "function": "f"}}],
  "outputs": {"fragment": {"color": 0.5}}})";
}

// "" when the property holds for `bytes`, using (and emptying) the scratch folder `root`.
inline std::string functionFileProperty(std::string_view bytes, const std::filesystem::path& root) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::remove_all(root, ec);
  fs::create_directories(root, ec);
  if (ec) return "";  // the scratch folder is not usable: nothing to check
  auto write = [&](const fs::path& p, std::string_view text) {
    std::FILE* f = std::fopen(p.c_str(), "wb");
    if (!f) return false;
    bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    return std::fclose(f) == 0 && ok;
  };
  if (!write(root / "f.glsl", bytes) || !write(root / "g.json", functionFileGraph())) return "";
  Diagnostics diags;
  auto graph = loadGraphFile((root / "g.json").string(), diags);
  if (!graph) return failure("the fixed graph does not load", diags);
  // The node reaches the output only when the function returns a float: otherwise the
  // graph compiles without it, and the file is checked all the same (resolve makes it).
  auto result = compileGraph(*graph, defaultRegistry(), CompileOptions{}, diags);
  if (std::string why = generatedCodeRejected(diags); !why.empty()) return why;
  if (result) return diags.hasErrors() ? failure("a result returned with errors", diags) : "";
  if (std::string why = checkErrors(diags); !why.empty()) return why;
  // Lines as glslang counts them, and so the diagnostics: at LF alone (a lone CR ends none).
  long lines = 1;
  for (char c : bytes) lines += c == '\n';
  for (const auto& d : diags.all())
    if (d.where.file.str().ends_with("f.glsl") && d.where.line > lines)
      return failure("an error placed after the file's last line", diags);
  return "";
}

}  // namespace wg::fuzz
