// "Model only what a scene needs", measured: for each graph, what the compile kept against
// everything that exists — nodes, render passes, render-target memory (as the runtime's
// pass planner allocates them at 1280x720), uniforms, samplers and GLSL library functions —
// and how many declared uniforms glslang's reflection finds read (all of them, or the
// generator is declaring something unused).
//
//   build/bin/wg_scene_model graphs/*.json        (a markdown table on stdout)
#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include "codegen/compile.h"
#include "codegen/glslang_validate.h"
#include "core/graph_io.h"
#include "nodes/glsl_library.h"
#include "nodes/registry.h"
#include "runtime/pass_plan.h"

namespace {

std::string mib(size_t bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f MiB", static_cast<double>(bytes) / (1024.0 * 1024.0));
  return buf;
}

// Every pass the runtime implements, planned together: the whole menu a graph picks from.
wg::rt::PassPlan everyPass(const wg::rt::PlanOptions& options) {
  wg::Manifest all;
  for (const auto& row : wg::renderPassTable())
    if (row.id != wg::RenderPass::OpaqueScene) all.passes.push_back(row.id);  // always runs, never listed
  return wg::rt::planPasses(all, options);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace wg;
  if (argc < 2) {
    std::fprintf(stderr, "usage: wg_scene_model GRAPH.json...\n");
    return 2;
  }
  rt::PlanOptions plan;  // 1280x720, RGBA8, 128^2 cube faces: what `watergraph render` uses
  rt::PassPlan all = everyPass(plan);
  const size_t libraryFunctions = GlslLibrary::builtin().items().size();

  std::printf("| graph | nodes kept | passes | render targets | uniforms: builtin + parameters (of the graph's) | samplers | GLSL functions | "
              "uniforms read (glslang reflection, per target) |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  int status = 0;
  for (int i = 1; i < argc; ++i) {
    Diagnostics diags;
    auto g = loadGraphFile(argv[i], diags);
    if (!g) {
      for (const auto& d : diags.sorted()) std::fprintf(stderr, "%s\n", formatText(d).c_str());
      status = 1;
      continue;
    }
    CompileOptions options;
    auto r = compileGraph(*g, defaultRegistry(), options, diags);
    if (!r) {
      for (const auto& d : diags.sorted()) std::fprintf(stderr, "%s\n", formatText(d).c_str());
      status = 1;
      continue;
    }
    const auto& m = r->manifest;
    rt::PassPlan used = rt::planPasses(m, plan);
    std::string passes;
    for (auto p : used.passes) passes += std::string(passes.empty() ? "" : ", ") + rt::passName(p);
    size_t parameters = g->parameters.size();
    size_t uniforms = m.uniforms.size(), fromParameters = 0;
    for (const auto& u : m.uniforms) fromParameters += u.parameter.has_value();
    size_t samplers = m.textures.size();
    std::string reflection;
    for (Target t : allTargets()) {
      EmitResult er = emitProgram(r->program, t, "g.json");
      std::vector<ShaderSource> sources;
      for (const auto& sh : er.shaders)
        sources.push_back({sh.stage, "g." + std::string(targetName(t)) + "." + std::string(stageExtension(sh.stage)), sh.text});
      auto active = activeUniforms(t, sources);
      std::set<std::string> activeSet = active ? std::set<std::string>(active->begin(), active->end()) : std::set<std::string>();
      size_t declared = er.uniforms.size() + er.textures.size(), read = 0;
      for (const auto& u : er.uniforms) read += activeSet.count(u.name);
      for (const auto& tex : er.textures) read += activeSet.count(tex.name);
      if (read != declared) status = 1;
      reflection += std::string(reflection.empty() ? "" : ", ") + std::string(targetName(t)) + " " + std::to_string(read) +
                    "/" + std::to_string(declared);
    }
    std::printf("| %s | %d/%d | %zu/%zu: %s | %zu/%zu: %s of %s | %zu + %zu/%zu | %zu | %zu/%zu | %s |\n", g->name.c_str(),
                r->nodesKept, r->nodesTotal, used.passes.size(), all.passes.size(), passes.c_str(), used.targets.size(),
                all.targets.size(), mib(used.totalBytes()).c_str(), mib(all.totalBytes()).c_str(), uniforms - fromParameters,
                fromParameters, parameters, samplers, m.functions.size(), libraryFunctions, reflection.c_str());
  }
  return status;
}
