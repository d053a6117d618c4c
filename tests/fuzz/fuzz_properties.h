#pragma once
// The properties the fuzz targets check, as plain functions so that the regression test
// (tests/robustness/fuzz_regressions_test.cpp) replays every saved input through exactly
// the same checks in the ordinary test suite. Each returns "" when the property holds,
// else what failed (with the diagnostics). Crashes, sanitizer reports, exceptions and
// stack overflows are failures too; the caller sees those as the process dying.
#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>

#include "codegen/compile.h"
#include "core/diagnostic.h"
#include "core/graph_io.h"
#include "json_reader_property.h"
#include "nodes/registry.h"

namespace wg::fuzz {

// How many inputs pipelineProperty saw, and how many compiled for every target (the fuzz
// targets print both at exit: the share that reached glslang).
inline std::size_t pipelineInputs = 0, pipelineCompiled = 0;

inline std::string failure(const std::string& what, const Diagnostics& diags) {
  std::string s = what;
  for (const auto& d : diags.sorted()) s += "\n  " + formatText(d);
  return s;
}

// A clear error: a message and a line:col inside the file (the only error without one,
// the 16 MiB size limit, is refused before parsing and fuzz inputs are smaller).
inline std::string checkErrors(const Diagnostics& diags) {
  if (!diags.hasErrors()) return failure("no error reported", diags);
  for (const auto& d : diags.all()) {
    if (d.severity != Severity::Error) continue;
    if (d.where.line < 1 || d.where.col < 1) return failure("an error without a line:col", diags);
    if (d.message.empty()) return failure("an error without a message", diags);
  }
  return "";
}

// The loader: a graph exactly when no error; errors are clear; an accepted graph survives
// the canonical save: saveGraph(parse(saveGraph(g))) == saveGraph(g) (core/graph_io.h).
inline std::string loaderProperty(std::string_view text) {
  if (std::string why = jsonReaderProperty(text); !why.empty()) return why;
  Diagnostics diags;
  auto graph = parseGraph(text, "fuzz.json", diags);
  if (!graph) return checkErrors(diags);
  if (diags.hasErrors()) return failure("a graph returned with errors", diags);
  std::string canonical = saveGraph(*graph);
  Diagnostics again;
  auto reparsed = parseGraph(canonical, "fuzz.json", again);
  if (!reparsed) return failure("the canonical form of an accepted graph does not load:\n" + canonical, again);
  if (saveGraph(*reparsed) != canonical) return failure("the canonical form is not stable:\n" + canonical, again);
  return "";
}

// glslang rejecting generated code (WG040, WG041) for a graph the resolver accepted: a
// compiler bug even though it is reported. "" when it did not.
inline std::string generatedCodeRejected(const Diagnostics& diags) {
  for (const auto& d : diags.all())
    if (d.severity == Severity::Error && (d.code == DiagCode::GlslRejected || d.code == DiagCode::SpirvRejected))
      return failure("glslang rejected generated code for a graph the compiler accepted", diags);
  return "";
}

// The whole pipeline, every target, glslang validation on: a clear error, or GLSL that
// glslang accepts for every target. glslang rejecting generated code (WG040, WG041) is a
// compiler bug even though it is reported: a graph the resolver accepted must give valid
// GLSL. A result holds each target's vertex and fragment shader, SPIR-V and a manifest.
inline std::string pipelineProperty(std::string_view text) {
  ++pipelineInputs;
  Diagnostics diags;
  auto graph = parseGraph(text, "fuzz.json", diags);
  if (!graph) return checkErrors(diags);
  CompileOptions options;  // every target, validation on
  auto result = compileGraph(*graph, defaultRegistry(), options, diags);
  if (std::string why = generatedCodeRejected(diags); !why.empty()) return why;
  if (!result) return checkErrors(diags);
  if (diags.hasErrors()) return failure("a result returned with errors", diags);
  bool manifest = false, spirv = false;
  int shaders = 0;
  auto endsWith = [](std::string_view s, std::string_view suffix) {
    return s.size() >= suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
  };
  for (const auto& f : result->files) {
    if (f.contents.empty()) return failure("empty output file " + f.name, diags);
    manifest |= endsWith(f.name, ".manifest.json");
    spirv |= endsWith(f.name, ".spv");
    shaders += endsWith(f.name, ".vert") || endsWith(f.name, ".frag");
  }
  if (!manifest || !spirv || shaders < 6) return failure("a result without every target's files", diags);
  ++pipelineCompiled;
  return "";
}

}  // namespace wg::fuzz

namespace wg::fuzz {
inline void printPipelineStats() {
  std::fprintf(stderr, "watergraph: %zu inputs, %zu compiled for every target\n", pipelineInputs, pipelineCompiled);
}
}  // namespace wg::fuzz
