// Nothing the tool decides searches the text of the shaders it generated. check's read-back
// is planned from the ShaderPlan (codegen/readback_taps.h, accuracy/readback.h); the planner
// decides which locals, declarations and library items a stage keeps from the values the
// nodes emit (core/emit_context.h: a GlslExpr carries what it reads and calls), not from
// their text. This greps the sources outside tests for the helpers and searches those
// decisions used before, so none comes back:
//   - the text-based read-back: findMain, samplerUse, callEnd, a search for main() or for a
//     texture() call;
//   - codegen/plan_stage's scan of stage bodies for wg_/WG_ names (the library items a stage
//     declares), and the library's scanner of code text applied to generated code
//     (GlslLibrary::itemsFor, removed; libraryIdentifiers reads only the library's own
//     hand-written items);
//   - the WebGPU client's regexes over the runtime's shaders (clients/webgpu): the scene
//     description now carries each in the form naga reads with a declaration table
//     (runtime/webgpu_shader_form.h), which the client binds from;
//   - codegen/plan_body's readsName (which temporaries an expression's text names),
//     isGlslName (whether an output's text is a name), the search of the kept text for the
//     names an op declared (forgetUnread), and a fetch's coordinate compared with the screen
//     uv's name.
//   - the three.js client's cut of the `#version 300 es` line from the description's
//     runtime shaders and the compiled es300 stages (withoutVersion, withoutVersionLine):
//     `watergraph scene` writes each ES shader's body and version apart ("three".shaders)
//     and `compile --target es300` each stage's body beside it (<stage>.body and the
//     target's "glsl_version"). The web clients' sources do not even name the directive
//     (TheWebClientsNeverHandleAVersionLine);
//   - `--explain-frequency`'s cost estimate read from the fragment lines' text (GlslCost over
//     frag->body and frag->locals, codegen/frequency_report.cpp): the planner counts each
//     line's operations from the values as it writes them (PlannedStatement::cost). GlslCost
//     now counts only the GLSL library's own hand-written items (what one call of a library
//     function costs), confined to its file; the counter of the pieces a node writes is
//     confined to the value type that appends them (core/emit_context.cpp).
//   - the WGSL target's translation of whole stage bodies (Translator::statements over a
//     stage's locals and body text, re-discovering which lines declare which local of which
//     type) and its attribution of an error by re-translating growing prefixes of that text
//     split at '\n' (opOfFailingLine): the emitter walks the plan's statements
//     (PlannedStatement: declaration or assignment, the declared Type, the name, the op) and
//     a refusal is the op of its own statement.
// The WGSL translator (wgsl::Translator, confined to its files and codegen/emit_wgsl.cpp)
// reads, besides the library's own hand-written items, each planned expression the nodes and
// the planner wrote, one at a time by the GLSL subset's grammar, with every name's type from
// the plan (the globals the module declares, the locals declared before it) — never a
// stage's text. The user's own edit of a shader (check --mutate, probe --mutate) is a text
// edit by design and searches for the user's text.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "test_support.h"

namespace wg {
namespace {

const char* const kForbidden[] = {
    // check's read-back
    "findMain", "samplerUse", "callEnd", ".find(\"void main", ".rfind(\"void main", ".find(\"texture(",
    ".find(std::string(\"texture(", ".find(\"gl_FragColor", ".find(\"fragColor",
    // the library items a stage declares
    "find(\"wg_\")", "find(\"WG_\")", "callsLibrary", "itemsFor(",
    // the locals and declarations an op's kept text reads
    "readsName(", "isGlslName(", "kept.find(", "f.coord == kSurfaceScreenUv",
    // the frequency report's count of the fragment lines' text
    "glsl.of(", "frag->body.find(", "codegen/glsl_cost.h",
    // the WGSL target's translation of whole stage bodies and its search for the failing line
    "opOfFailingLine", "translator_.statements(", "Translator::statements", "parseStatements(",
    // the WebGPU client's rewriting of the runtime's ES shaders for naga: uniform lines into a
    // block, `in` lines given locations, the header's macros, main() wrapped, samplers into
    // textures, texelFetch calls, bindings read back out of naga's WGSL
    "glsl450ForNaga", "replace(/^uniform", "replace(/^in ", "replace('#define WG_", "void main\\(\\)",
    "RegExp(`texelFetch", "matchAll(/@binding", "#version 300 es\\n(?:precision",
    // the three.js client's cut of the version line (its regex: /^\s*#version\s+300\s+es.../)
    "withoutVersion", "#version\\s",
};

// Names allowed only in the files listed (paths relative to the source root).
const std::map<std::string, std::set<std::string>> kConfined = {
    // The library's scanner reads the library's own items (their uses of each other).
    {"libraryIdentifiers(", {"nodes/glsl_library.h", "nodes/glsl_library.cpp"}},
    // What one call of a library function costs, counted from the library's own items.
    {"GlslCost", {"nodes/glsl_library_cost.h", "nodes/glsl_library_cost.cpp"}},
    // The counter of GLSL pieces: the pieces a node appends to a value, and the library's items.
    {"countGlslOperations(", {"core/glsl_operation_count.h", "core/glsl_operation_count.cpp", "core/emit_context.cpp",
                               "nodes/glsl_library_cost.cpp"}},
    // The WGSL target translates the library's items and each planned expression (with the
    // plan's types), never a stage's text.
    {"Translator", {"codegen/wgsl_translate.h", "codegen/wgsl_translate.cpp", "codegen/emit_wgsl.cpp"}},
};

bool isSource(const std::filesystem::path& p) {
  static const char* const kExtensions[] = {".cpp", ".h", ".hpp", ".c", ".js", ".mjs", ".ts"};
  for (const char* e : kExtensions)
    if (p.extension() == e) return true;
  return false;
}

// Every source file under `dir` (node_modules left out), as relative path -> text.
std::map<std::string, std::string> sourcesUnder(const char* dir) {
  std::map<std::string, std::string> out;
  const std::filesystem::path top = test::sourcePath(".");
  const std::filesystem::path root = test::sourcePath(dir);
  if (!std::filesystem::exists(root)) return out;
  for (auto it = std::filesystem::recursive_directory_iterator(root); it != std::filesystem::recursive_directory_iterator(); ++it) {
    if (it->is_directory() && it->path().filename() == "node_modules") {
      it.disable_recursion_pending();
      continue;
    }
    if (!it->is_regular_file() || !(isSource(it->path()) || it->path().extension() == ".html")) continue;
    std::ifstream in(it->path(), std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    out[std::filesystem::relative(it->path(), top).generic_string()] = text.str();
  }
  return out;
}

// The web clients take every shader as watergraph writes it for them (three.js: a body and
// its version apart; WebGPU: a form naga reads as it is), so nothing in them, tests and
// pages included, names the version directive: a client that finds, cuts or writes a
// "#version" line in a shader's text would have to.
TEST(SourceTree, TheWebClientsNeverHandleAVersionLine) {
  const auto sources = sourcesUnder("clients");
  size_t three = 0;
  for (const auto& [relative, text] : sources) {
    three += relative.starts_with("clients/three/") ? 1 : 0;
    EXPECT_EQ(text.find("#version"), std::string::npos) << relative << " names the #version directive";
  }
  // Reached: the three.js client's modules, tests and pages, and the WebGPU client's.
  EXPECT_TRUE(sources.count("clients/three/watergraph-three.js"));
  EXPECT_TRUE(sources.count("clients/three/watergraph-passes.js"));
  EXPECT_TRUE(sources.count("clients/three/example/gallery.js"));
  EXPECT_TRUE(sources.count("clients/three/test/color.test.mjs"));
  EXPECT_TRUE(sources.count("clients/webgpu/watergraph-webgpu-ocean.js"));
  EXPECT_GT(three, 15u);
}

TEST(SourceTree, NoSearchOfGeneratedShaderText) {
  size_t files = 0;
  const std::filesystem::path top = test::sourcePath(".");
  for (const char* dir : {"accuracy", "cli", "runtime", "editor", "codegen", "clients", "core", "nodes", "bench"}) {
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
      const std::string relative = std::filesystem::relative(it->path(), top).generic_string();
      for (const char* pattern : kForbidden)
        EXPECT_EQ(s.find(pattern), std::string::npos) << relative << " contains " << pattern;
      for (const auto& [pattern, allowed] : kConfined)
        if (!allowed.count(relative))
          EXPECT_EQ(s.find(pattern), std::string::npos) << relative << " contains " << pattern << ", allowed only in its own files";
    }
  }
  EXPECT_GT(files, 100u);  // the tree was found
}

}  // namespace
}  // namespace wg
