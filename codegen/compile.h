#pragma once
// The whole pipeline for one graph: load -> resolve -> passes -> emit per target ->
// glslang validation -> manifest. Nothing is written here; see output_files.h.
#include <optional>
#include <string>
#include <vector>

#include "codegen/emit_glsl.h"
#include "codegen/glslang_validate.h"
#include "codegen/manifest.h"
#include "codegen/target.h"
#include "core/diagnostic.h"
#include "core/graph.h"
#include "core/program.h"
#include "core/registry.h"

namespace wg {

struct CompileOptions {
  std::vector<Target> targets = allTargets();
  bool validate = true;  // glslang; off only for tests of the emitter itself
  std::string preset;    // a graph preset whose values become the parameter defaults ("" none)
  bool tessellation = true;  // false: every target draws the mesh as it is (as es300 always does)
  // Build every other preset that sets node options too (checkOtherPresets): on for the
  // CLI's compile and validate; off where one graph is compiled over and over in variants
  // of its knobs (tune, bench), whose graph was checked when the run began.
  bool checkPresets = true;
  // Also GRAPH.wgsl for WebGPU (codegen/compile_wgsl.h), listed in the manifest as "wgsl".
  bool wgsl = false;
};

struct OutputFile {
  std::string name;      // "lake.glsl330.frag"
  std::string contents;  // text, or the SPIR-V words as bytes
};

struct CompileResult {
  Program program;  // after the passes
  std::vector<OutputFile> files;  // shaders, SPIR-V and the manifest, in a stable order
  Manifest manifest;  // also among `files`, as JSON
  int nodesTotal = 0;
  int nodesKept = 0;  // graph nodes some op still comes from (an expanded node counts once)
  std::vector<int> wgslLineOp;  // with CompileOptions::wgsl: GRAPH.wgsl's line -> op map
  // How the shaders were planned, so waterPlan can plan a target's again (the plans
  // themselves are not kept: a big graph's are megabytes).
  std::string sourceName;
  bool tessellation = true;
};

// The plan `result`'s shaders for `target` were emitted from, made again from its program:
// emitGlsl of it gives the compile's texts byte for byte (check's tap frames are variants
// of its fragment stage, codegen/readback_taps.h).
ShaderPlan waterPlan(const CompileResult& result, Target target);

// glslang's messages about generated shaders as diagnostics at the graph node whose op wrote
// the line (and the subgraph instances it lies in), or at the graph file for a line no op wrote.
void reportRejectedShaders(const ValidationResult& vr, const std::vector<EmittedShader>& shaders,
                           const std::vector<ShaderSource>& sources, const Program& program, DiagCode code,
                           Diagnostics& diags);

// Runs resolve and the pass recipe; the Program is ready to emit.
std::optional<Program> buildProgram(const Graph& graph, const Registry& registry, Diagnostics& diags);

std::optional<CompileResult> compileGraph(const Graph& graph, const Registry& registry,
                                          const CompileOptions& options, Diagnostics& diags);

// The output file base name for a graph file: its name without folder and ".json".
std::string graphBaseName(const std::string& path);

}  // namespace wg
