// The passes together (the recipe on an example graph), then the emitter: only what is
// used appears in the GLSL, and names are generated. Each pass alone has its own file,
// pass_<name>_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <regex>

#include "codegen/compile.h"
#include "pass_test_support.h"

namespace wg {
namespace {

using namespace passtest;

// --- the recipe and the emitter ------------------------------------------------------

struct Compiled {
  std::optional<CompileResult> result;
  std::string diagnostics;
  std::string text(const std::string& suffix) const {
    if (!result) return "";
    for (const auto& f : result->files)
      if (f.name.size() >= suffix.size() && f.name.compare(f.name.size() - suffix.size(), suffix.size(), suffix) == 0)
        return f.contents;
    return "";
  }
  // Every GLSL file, concatenated.
  std::string allGlsl() const {
    std::string s;
    if (result)
      for (const auto& f : result->files)
        // Each shader once: not its SPIR-V, the manifest, or an es300 stage's .body (its text again).
        if (f.name.find(".spv") == std::string::npos && f.name.find(".manifest") == std::string::npos && !f.name.ends_with(".body"))
          s += f.contents;
    return s;
  }
};

Compiled compileText(const std::string& json, const std::string& file = "test.json") {
  Compiled c;
  Diagnostics diags;
  auto graph = parseGraph(json, file, diags);
  if (graph) c.result = compileGraph(*graph, defaultRegistry(), CompileOptions{}, diags);
  c.diagnostics = allText(diags);
  return c;
}

Compiled compileExample(const std::string& name) {
  return compileText(test::readFile(test::sourcePath("graphs/" + name + ".json")), name + ".json");
}

TEST(Recipe, ShelfFoldsItsStaticSlopeAndPrunesTheDebugNode) {
  Compiled c = compileExample("shelf");
  ASSERT_TRUE(c.result) << c.diagnostics;
  const Program& p = c.result->program;
  EXPECT_FALSE(findOp(p, "debug_depth"));
  EXPECT_FALSE(findOp(p, "slope_scaled"));
  EXPECT_FALSE(hasParameter(p, "slope"));
  EXPECT_FALSE(hasParameter(p, "ior"));
  EXPECT_TRUE(hasParameter(p, "sky"));
  EXPECT_TRUE(findRemoval(p, "debug_depth"));
  EXPECT_TRUE(findRemoval(p, "slope_scaled"));
  EXPECT_EQ(c.result->nodesTotal, 8);
  // One op per kept node, and one more: the linearisation of the colour parameter sky
  // (no graph node, so not counted).
  EXPECT_TRUE(findOp(p, "$sky"));
  EXPECT_EQ(c.result->nodesKept + 1, static_cast<int>(p.ops.size()));
}

// kept/total counts nodes: classic_webgl's du/dv node computes its scroll in ops of its
// own (a per-draw split), and still counts once; nothing is kept that was not written.
TEST(Compile, NodesKeptCountsNodesNotOps) {
  Compiled classic = compileExample("classic_webgl");
  ASSERT_TRUE(classic.result) << classic.diagnostics;
  EXPECT_GT(classic.result->program.ops.size(), static_cast<size_t>(classic.result->nodesKept));
  EXPECT_LE(classic.result->nodesKept, classic.result->nodesTotal);
  EXPECT_EQ(classic.result->nodesKept, classic.result->nodesTotal) << "every node of classic_webgl is used";
}

TEST(Emit, OnlyCalledLibraryFunctionsAppear) {
  Compiled lake = compileExample("lake");
  ASSERT_TRUE(lake.result) << lake.diagnostics;
  for (const char* target : {"glsl330", "es300", "vk450"}) {
    SCOPED_TRACE(target);
    std::string frag = lake.text(std::string(".") + target + ".frag");
    std::string vert = lake.text(std::string(".") + target + ".vert");
    ASSERT_FALSE(frag.empty());
    EXPECT_NE(frag.find("wg_fresnel_schlick("), std::string::npos);
    EXPECT_EQ(frag.find("wg_fresnel_exact"), std::string::npos);
    EXPECT_EQ(frag.find("wg_fresnel_power"), std::string::npos);
    EXPECT_EQ(frag.find("wg_fresnel_schlick_from_below"), std::string::npos);
    EXPECT_EQ(frag.find("wg_depth_tint_smooth"), std::string::npos);
    EXPECT_EQ(vert.find("wg_fresnel"), std::string::npos) << "the vertex stage calls no fresnel";
  }
  const auto& functions = lake.result->manifest.functions;
  EXPECT_NE(std::find(functions.begin(), functions.end(), "wg_fresnel_schlick"), functions.end());
  EXPECT_EQ(std::find(functions.begin(), functions.end(), "wg_fresnel_exact"), functions.end());

  Compiled shelf = compileExample("shelf");
  ASSERT_TRUE(shelf.result) << shelf.diagnostics;
  std::string frag = shelf.text(".glsl330.frag");
  EXPECT_NE(frag.find("wg_fresnel_exact("), std::string::npos);
  EXPECT_EQ(frag.find("wg_fresnel_schlick"), std::string::npos);
  EXPECT_NE(frag.find("wg_depth_tint_smooth("), std::string::npos);
  EXPECT_EQ(frag.find("wg_depth_tint_linear"), std::string::npos);
}

TEST(Emit, EveryLibraryFunctionDefinedIsCalled) {
  // A definition nobody calls is dead code: each `float wg_x(` defined must be called
  // somewhere else in the same shader.
  for (const char* name : {"lake", "shelf"}) {
    Compiled c = compileExample(name);
    ASSERT_TRUE(c.result) << c.diagnostics;
    for (const auto& f : c.result->files) {
      if (f.name.find(".spv") != std::string::npos || f.name.find(".manifest") != std::string::npos) continue;
      std::regex def(R"((?:^|\n)(?:float|vec2|vec3|vec4|bool|int)\s+(wg_\w+)\s*\()");
      for (auto it = std::sregex_iterator(f.contents.begin(), f.contents.end(), def); it != std::sregex_iterator(); ++it) {
        std::string fn = (*it)[1];
        size_t defAt = static_cast<size_t>(it->position(1));
        size_t calls = 0;
        for (size_t at = f.contents.find(fn + "("); at != std::string::npos; at = f.contents.find(fn + "(", at + 1))
          if (at != defAt) ++calls;
        EXPECT_GT(calls, 0u) << f.name << " defines " << fn << " but never calls it";
      }
    }
  }
}

TEST(Emit, GraphIdsAreSanitisedInGeneratedNames) {
  Compiled c = compileText(graphJson(
      R"({"id": "weird__Name", "type": "fresnel", "options": {"model": "schlick"}},
         {"id": "gl_Position", "type": "mul", "inputs": {"a": "weird__Name.reflectance", "b": "$tint__amount"}},
         {"id": "a_very_long_node_identifier_that_goes_on_and_on", "type": "uv"},
         {"id": "l", "type": "length", "inputs": {"x": "a_very_long_node_identifier_that_goes_on_and_on.out"}},
         {"id": "sum", "type": "add", "inputs": {"a": "gl_Position.out", "b": "l.out"}})",
      R"("fragment": {"alpha": "sum.out"})", R"("tint__amount": {"type": "float", "default": 0.5})"));
  ASSERT_TRUE(c.result) << c.diagnostics;
  std::string glsl = c.allGlsl();
  EXPECT_EQ(glsl.find("__"), std::string::npos) << "GLSL reserves identifiers containing '__'";
  EXPECT_NE(glsl.find("weird_Name"), std::string::npos);
  EXPECT_NE(glsl.find("p_tint_amount"), std::string::npos);
  EXPECT_EQ(glsl.find("a_very_long_node_identifier_that_goes_on_and_on"), std::string::npos);
  // The id 'gl_Position' only ever appears inside a generated name (n1_gl_Position); the
  // builtin itself is only written by the vertex stage ("gl_Position = ...").
  size_t realWrites = 0;
  for (size_t at = glsl.find("gl_Position"); at != std::string::npos; at = glsl.find("gl_Position", at + 1)) {
    bool insideName = at > 0 && (std::isalnum(static_cast<unsigned char>(glsl[at - 1])) || glsl[at - 1] == '_');
    bool builtinWrite = glsl.compare(at, 14, "gl_Position = ") == 0 && !insideName;
    EXPECT_TRUE(insideName || builtinWrite) << glsl.substr(at > 20 ? at - 20 : 0, 60);
    realWrites += builtinWrite;
  }
  EXPECT_EQ(realWrites, 3u) << "one gl_Position write per vertex shader (3 targets)";
}

TEST(Emit, GraphStringsNeverReachTheShader) {
  // Descriptions and parameter descriptions are data for the manifest and editor only.
  Compiled c = compileText(
      "{\"version\": 1, \"name\": \"t\", \"description\": \"*/ #error injected\\n#define x\","
      "\"parameters\": {\"a\": {\"type\": \"float\", \"default\": 1, \"description\": \"*/ void main() {} /*\"}},"
      "\"nodes\": [{\"id\": \"u\", \"type\": \"uv\"}, {\"id\": \"l\", \"type\": \"length\", \"inputs\": {\"x\": \"u.out\"}},"
      "{\"id\": \"m\", \"type\": \"mul\", \"inputs\": {\"a\": \"l.out\", \"b\": \"$a\"}}],"
      "\"outputs\": {\"fragment\": {\"alpha\": \"m.out\"}}}");
  ASSERT_TRUE(c.result) << c.diagnostics;
  std::string glsl = c.allGlsl();
  EXPECT_EQ(glsl.find("injected"), std::string::npos);
  EXPECT_EQ(glsl.find("void main() {} /*"), std::string::npos);
  EXPECT_EQ(glsl.find("#define"), std::string::npos);
}

TEST(Emit, SourceFileNameCannotBreakOutOfTheHeaderComment) {
  // The header comment names the graph file; a newline in that name must not start a
  // line of GLSL (this name would otherwise inject a valid preprocessor line).
  Compiled c = compileText(graphJson(R"({"id": "u", "type": "uv"}, {"id": "l", "type": "length", "inputs": {"x": "u.out"}})",
                                     R"("fragment": {"alpha": "l.out"})"),
                           "odd\n#define WG_INJECTED 1\n#pragma .json");
  ASSERT_TRUE(c.result) << c.diagnostics;
  for (const auto& line : test::splitLines(c.allGlsl()))
    EXPECT_NE(line.rfind("#define", 0), 0u) << line;
}

TEST(Emit, UnusedParametersProduceNoUniform) {
  Compiled shelf = compileExample("shelf");
  ASSERT_TRUE(shelf.result) << shelf.diagnostics;
  std::string glsl = shelf.allGlsl();
  EXPECT_EQ(glsl.find("p_ior"), std::string::npos) << "'ior' is declared but never read";
  EXPECT_EQ(glsl.find("p_slope"), std::string::npos) << "'slope' is static: compiled in";
  EXPECT_NE(glsl.find("p_sky"), std::string::npos);
  for (const auto& u : shelf.result->manifest.uniforms) {
    if (!u.parameter) continue;
    EXPECT_NE(u.parameter->name, "ior");
    EXPECT_NE(u.parameter->name, "slope");
  }

  Compiled c = compileText(graphJson(R"({"id": "u", "type": "uv"}, {"id": "l", "type": "length", "inputs": {"x": "u.out"}})",
                                     R"("fragment": {"alpha": "l.out"})",
                                     R"("never_read": {"type": "vec3", "default": [1, 2, 3]})"));
  ASSERT_TRUE(c.result) << c.diagnostics;
  EXPECT_EQ(c.allGlsl().find("never_read"), std::string::npos);
  EXPECT_EQ(c.allGlsl().find("uniform float p_"), std::string::npos);
}

TEST(Emit, UsedParametersAreUniformsInTheStageThatReadsThem) {
  Compiled lake = compileExample("lake");
  ASSERT_TRUE(lake.result) << lake.diagnostics;
  std::string frag = lake.text(".glsl330.frag");
  std::string vert = lake.text(".glsl330.vert");
  const std::pair<const char*, const char*> params[] = {
      {"p_shallow", "vec3"}, {"p_deep", "vec3"}, {"p_sky", "vec3"}, {"p_max_depth", "float"}, {"p_centre_depth", "float"}};
  for (const auto& [name, type] : params) {
    EXPECT_NE(frag.find(std::string("uniform ") + type + " " + name + ";"), std::string::npos) << name;
    EXPECT_EQ(vert.find(name), std::string::npos) << name << " is only read in the fragment stage";
  }
}

TEST(Emit, UnusedBuiltinsDeclareNothing) {
  // A graph that reads no uv declares no uv attribute and no uv varying.
  Compiled c = compileText(graphJson(R"({"id": "t", "type": "time"}, {"id": "s", "type": "sin", "inputs": {"x": "t.out"}})",
                                     R"("fragment": {"alpha": "s.out"})"));
  ASSERT_TRUE(c.result) << c.diagnostics;
  std::string glsl = c.allGlsl();
  EXPECT_EQ(glsl.find("a_uv"), std::string::npos);
  EXPECT_EQ(glsl.find("v_uv"), std::string::npos);
  EXPECT_EQ(glsl.find("a_normal"), std::string::npos);
  EXPECT_EQ(glsl.find("wg_fresnel"), std::string::npos);
}

}  // namespace
}  // namespace wg
