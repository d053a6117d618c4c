#include "codegen/compile.h"

#include "codegen/compile_wgsl.h"

#include <algorithm>
#include <filesystem>
#include <iterator>
#include <string_view>
#include <unordered_set>
#include <utility>
#include <vector>

#include "codegen/glslang_validate.h"
#include "codegen/manifest_build.h"
#include "codegen/ocean_module_js.h"
#include "codegen/passes.h"
#include "core/color_parameters.h"
#include "core/preset.h"
#include "core/resolve.h"
#include "core/shown_text.h"

namespace wg {

std::string graphBaseName(const std::string& path) {
  std::filesystem::path p(path);
  std::string name = p.filename().string();
  if (name.size() > 5 && name.compare(name.size() - 5, 5, ".json") == 0) name.resize(name.size() - 5);
  // The output files are named from it and the manifest (JSON, UTF-8) names them: a byte
  // that is not UTF-8 becomes '_' (core/shown_text.h), so every name written can be listed.
  std::string named;
  for (std::size_t i = 0; i < name.size();) {
    std::size_t n = utf8SequenceLength(name, i);
    named += n ? name.substr(i, n) : "_";
    i += n ? n : 1;
  }
  return named;
}

bool runPassRecipe(Program& program, PassContext& ctx, const PassHooks* hooks) {
  auto run = [&](std::string_view name, PassResult (*pass)(Program&, PassContext&)) {
    if (hooks && hooks->before) hooks->before(name);
    PassResult r = pass(program, ctx);
    if (hooks && hooks->after) hooks->after(name);
    return r;
  };
  run("bypass", bypassPass);
  run("specialise", specialisePass);
  run("prune", prunePass);
  // fold, simplify and cse expose more of each other's work, so they take turns until none
  // changes anything (bounded: each change removes at least one op; at most 8 rounds). Each
  // is one forward sweep over inputs already rewritten, so running it twice on the same
  // program changes nothing: a pass whose turn comes when nothing changed since its own
  // last run is not run again, and the turns end there.
  struct Turn {
    std::string_view name;
    PassResult (*pass)(Program&, PassContext&);
  };
  const Turn turns[] = {{"fold", foldPass}, {"simplify", simplifyPass}, {"cse", csePass}};
  constexpr int kTurns = static_cast<int>(std::size(turns));
  int lastChanged = -1;  // the turn that last changed the program
  for (int step = 0; step < 8 * kTurns; ++step) {
    int k = step % kTurns;
    if (k == lastChanged) break;
    if (run(turns[k].name, turns[k].pass) == PassResult::Changed) lastChanged = k;
    else if (lastChanged < 0 && k == kTurns - 1) break;  // a first round that changed nothing
  }
  run("prune_final", prunePass);
  // The rewrites compact the op list in place; what the passes removed is given back once,
  // here, rather than by a new array per pass.
  program.ops.shrink_to_fit();
  return run("stages", stagePass) != PassResult::Failed;
}

std::optional<Program> buildProgram(const Graph& graph, const Registry& registry, Diagnostics& diags) {
  auto program = resolveGraph(graph, registry, diags);
  if (!program) return std::nullopt;
  PassContext ctx{diags};
  if (!runPassRecipe(*program, ctx)) return std::nullopt;
  return program;
}

namespace {

// A glslang message mapped back to the node whose code is on that line.
std::string spirvBytes(const std::vector<uint32_t>& words) {
  std::string bytes(words.size() * 4, '\0');
  for (size_t i = 0; i < words.size(); ++i)
    for (int b = 0; b < 4; ++b) bytes[i * 4 + static_cast<size_t>(b)] = static_cast<char>((words[i] >> (8 * b)) & 0xffu);
  return bytes;
}

}  // namespace

void reportRejectedShaders(const ValidationResult& vr, const std::vector<EmittedShader>& shaders,
                      const std::vector<ShaderSource>& sources, const Program& program, DiagCode code,
                      Diagnostics& diags) {
  for (const auto& m : vr.errors) {
    int op = -1;
    for (size_t s = 0; s < sources.size(); ++s)
      if (sources[s].fileName == m.fileName && m.line > 0 &&
          static_cast<size_t>(m.line) <= shaders[s].lineOp.size())
        op = shaders[s].lineOp[static_cast<size_t>(m.line - 1)];
    std::string where = m.fileName.empty() ? "link" : m.fileName + (m.line ? ":" + std::to_string(m.line) : "");
    if (op >= 0) {
      const Op& o = program.ops[static_cast<size_t>(op)];
      withInstanceNotes(diags.error(code, o.where, "generated GLSL rejected at " + where + ": " + m.text, o.nodeId), o);
    } else {
      diags.error(code, SourceRef{program.file, 0, 0}, "generated GLSL rejected at " + where + ": " + m.text);
    }
  }
}

namespace {

// Emits every target of `options` into `result.files` (validated when asked) and builds the
// manifest; false when glslang rejected a shader.
// `bodies`: per stage file of a target that writesStageBodies, its index in result.files and
// where its body starts.
bool emitTargets(const Program& program, const CompileOptions& options, const std::string& base,
                 const std::string& sourceName, CompileResult& result, Diagnostics& diags,
                 std::vector<std::pair<size_t, size_t>>& bodies) {
  bool ok = true;
  // One plan per distinct tessellation choice; each target wraps its plan in its dialect.
  TargetPlans plans = planTargets(program, options.targets, sourceName, options.tessellation);
  for (size_t ti = 0; ti < options.targets.size(); ++ti) {
    Target target = options.targets[ti];
    EmitResult er = emitGlsl(plans.of(ti), target);
    // The text moves into `sources` and from there into the result (a big graph's shaders
    // are megabytes); what stays in `er` (stages, line map) is what the validation
    // messages read.
    std::vector<ShaderSource> sources;
    for (auto& sh : er.shaders)
      sources.push_back({sh.stage, base + "." + std::string(targetName(target)) + "." + std::string(stageExtension(sh.stage)),
                         std::move(sh.text)});
    const size_t firstFile = result.files.size();
    for (const auto& src : sources) result.files.push_back({src.fileName, std::string()});
    if (options.validate) {
      ValidationResult vr = validateShaders(target, sources);
      if (!vr.ok) {
        bool spirvStage = !vr.errors.empty() && vr.errors.front().text.rfind("spirv-val", 0) == 0;
        reportRejectedShaders(vr, er.shaders, sources, program, spirvStage ? DiagCode::SpirvRejected : DiagCode::GlslRejected, diags);
        ok = false;
      } else {
        for (size_t s = 0; s < vr.spirv.size() && s < sources.size(); ++s)
          result.files.push_back({sources[s].fileName + ".spv", spirvBytes(vr.spirv[s])});
      }
    }
    for (size_t s = 0; s < sources.size(); ++s) {
      result.files[firstFile + s].contents = std::move(sources[s].text);
      if (writesStageBodies(target)) bodies.emplace_back(firstFile + s, er.shaders[s].bodyStart);
    }
  }
  if (!ok) return false;
  result.manifest = buildManifest(program, plans, base);
  return true;
}

// Every preset but the applied one that sets node options is built as well: some option
// values only a build can check (an expression's formula and inputs: the functions it
// calls, the type it gives), and every preset is checked on every compile and validate,
// not only when someone picks it. Its errors are reported as the preset's; the build is
// dropped. Called once the graph itself built, so nothing is reported twice.
bool checkOtherPresets(const Graph& graphAsWritten, std::string_view applied, const Registry& registry,
                       Diagnostics& diags) {
  bool ok = true;
  for (const Preset& preset : graphAsWritten.presets) {
    if (preset.name == applied ||
        std::none_of(preset.values.begin(), preset.values.end(), [](const PresetValue& v) { return v.isOption(); }))
      continue;
    Graph withPreset = graphAsWritten;
    Diagnostics local;
    local.keepSourcesOf(diags);  // a formula's error column counts the escapes before it
    if (applyPreset(withPreset, preset.name, local) && buildProgram(withPreset, registry, local)) continue;
    ok = false;
    for (Diagnostic d : local.all()) {
      if (d.severity != Severity::Error) continue;
      d.message = "with preset '" + preset.name + "': " + d.message;
      diags.add(std::move(d));
    }
  }
  return ok;
}

}  // namespace

ShaderPlan waterPlan(const CompileResult& result, Target target) {
  // As planTargets: a target tessellates when the graph asks and the target can.
  return planShaders(result.program, result.sourceName, tessellates(target, result.tessellation));
}

std::optional<CompileResult> compileGraph(const Graph& graphAsWritten, const Registry& registry,
                                          const CompileOptions& options, Diagnostics& diags) {
  Graph withPreset;
  if (!options.preset.empty()) {
    withPreset = graphAsWritten;
    if (!applyPreset(withPreset, options.preset, diags)) return std::nullopt;
  }
  const Graph& graph = options.preset.empty() ? graphAsWritten : withPreset;
  auto program = buildProgram(graph, registry, diags);
  if (!program) return std::nullopt;
  if (options.checkPresets && !checkOtherPresets(graphAsWritten, options.preset, registry, diags)) return std::nullopt;
  CompileResult result;
  result.nodesTotal = program->totalNodes;
  // Nodes, not ops: a node may expand into several ops (its per-draw split, its stages).
  std::unordered_set<std::string_view> keptNodes;
  for (const auto& op : program->ops)
    if (!isParameterLinearisation(op.nodeId)) keptNodes.insert(op.nodeId);
  result.nodesKept = static_cast<int>(keptNodes.size());
  std::string base = graphBaseName(graph.file.empty() ? graph.name : graph.file);
  std::string sourceName = std::filesystem::path(graph.file).filename().string();
  sourceName = validUtf8(sourceName);  // the manifest (JSON) may name it
  for (char& ch : sourceName) if (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f) ch = '?';  // stays in the // comment
  // The plans live inside emitTargets, so they are gone before the manifest's text is
  // written: a big graph's plans are megabytes that nothing after the manifest reads.
  std::vector<std::pair<size_t, size_t>> bodies;
  if (!emitTargets(*program, options, base, sourceName.empty() ? graph.name : sourceName, result, diags, bodies))
    return std::nullopt;
  // The es300 stages without their version line, copied once the plans are gone (the copy
  // is not held beside them at the compile's peak).
  for (const auto& [file, start] : bodies) {
    OutputFile body{result.files[file].name + std::string(kStageBodySuffix), result.files[file].contents.substr(start)};
    result.files.push_back(std::move(body));
  }
  if (options.wgsl &&
      !addWgslTarget(*program, base, sourceName.empty() ? graph.name : sourceName, result, diags, &result.wgslLineOp))
    return std::nullopt;
  result.manifest.preset = options.preset;
  result.sourceName = sourceName.empty() ? graph.name : sourceName;
  result.tessellation = options.tessellation;
  // A web target's client simulates the oceans from the module only the compiler can write.
  const bool web = options.wgsl || std::find(options.targets.begin(), options.targets.end(), Target::Es300) != options.targets.end();
  if (web && !result.manifest.oceans.empty()) {
    result.manifest.oceanModule = oceanModuleFileName(base);
    result.files.push_back({result.manifest.oceanModule, oceanModuleJs(base, *program, result.manifest.oceans)});
  }
  result.files.push_back({base + ".manifest.json", result.manifest.fileText()});
  result.program = std::move(*program);
  return result;
}

}  // namespace wg
