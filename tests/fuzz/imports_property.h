#pragma once
// The importer's property (wg_fuzz_imports, and the corpus replay in the test suite): an
// input is several graph files separated by NUL bytes, written as top.json, lib/f1.json,
// lib/f2.json, ... into a folder; top.json is loaded with its imports and compiled for
// every target. Whatever the files say — imports of each other, cycles, missing or
// outside paths, mismatched interfaces — the result is a clear error (every error with a
// file and line:col, in a file of the folder) or GLSL that glslang accepts, and the files
// a compiled graph says it read are files of the folder.
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "core/graph_imports.h"
#include "fuzz_properties.h"

namespace wg::fuzz {

inline constexpr std::size_t kMaxImportFiles = 6;

// Writes the files of `data` into `dir` (emptied first); returns their paths, top.json first.
inline std::vector<std::string> writeImportFiles(std::string_view data, const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::create_directories(dir + "/lib", ec);
  std::vector<std::string> paths;
  size_t start = 0;
  while (paths.size() < kMaxImportFiles) {
    size_t end = data.find('\0', start);
    std::string name = paths.empty() ? "top.json" : "lib/f" + std::to_string(paths.size()) + ".json";
    std::string path = dir + "/" + name;
    std::ofstream(path, std::ios::binary) << data.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
    paths.push_back(path);
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  return paths;
}

inline std::string importsProperty(std::string_view data, const std::string& dir) {
  std::vector<std::string> files = writeImportFiles(data, dir);
  Diagnostics diags;
  auto graph = loadGraphFile(files[0], diags);
  auto inFolder = [&](const std::string& path) { return path.rfind(dir + "/", 0) == 0; };
  if (!graph) {
    if (std::string why = checkErrors(diags); !why.empty()) return why;
    for (const auto& d : diags.all())
      if (d.severity == Severity::Error && !inFolder(d.where.file)) return failure("an error outside the folder", diags);
    return "";
  }
  for (const auto& f : graphFilesRead(*graph))
    if (!inFolder(f)) return failure("the graph says it read " + f, diags);
  CompileOptions options;
  auto result = compileGraph(*graph, defaultRegistry(), options, diags);
  if (std::string why = generatedCodeRejected(diags); !why.empty()) return why;
  if (!result) return checkErrors(diags);
  if (diags.hasErrors()) return failure("a result returned with errors", diags);
  return "";
}

}  // namespace wg::fuzz
