// Colour-managed values (core/color_parameters.h, docs/graph-format.md "Colour"): colour
// parameters reach the nodes through srgb_to_linear (in the shader for a uniform, folded to
// the exact linear constant for a static one); colour
// literals and defaults of colour ports are linearised at resolve time; data is untouched.
#include <cmath>

#include <gtest/gtest.h>

#include "codegen/compile.h"
#include "codegen/manifest.h"
#include "core/graph_io.h"
#include "pass_test_support.h"
#include "test_support.h"

namespace wg {
namespace color_parameters_test {

using namespace passtest;

// The IEC 61966-2-1 decoding written out here, independently of core/color_space.h.
double linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

// The colour output is `source` times the uv's length, so a uniform stays per draw and the
// colour per pixel.
std::string graphOf(const std::string& parameters, const std::string& source, const std::string& more = "") {
  return graphJson(R"({"id": "u", "type": "uv"}, {"id": "l", "type": "length", "inputs": {"x": "u.out"}},
                      {"id": "shade", "type": "mul", "inputs": {"a": ")" + source + R"(", "b": "l.out"}})" + more,
                   R"("fragment": {"color": "shade.out"})", parameters);
}

CompileResult compile(const std::string& json) {
  Diagnostics diags;
  auto graph = parseGraph(json, "test.json", diags);
  EXPECT_TRUE(graph) << allText(diags);
  if (!graph) return {};
  CompileOptions options;
  options.targets = {Target::Glsl330};
  auto r = compileGraph(*graph, defaultRegistry(), options, diags);
  EXPECT_TRUE(r) << allText(diags);
  return r ? std::move(*r) : CompileResult{};
}

std::string fragmentOf(const CompileResult& r) {
  for (const auto& f : r.files)
    if (f.name == "test.glsl330.frag") return f.contents;
  ADD_FAILURE() << "no fragment shader";
  return "";
}

int opsOfType(const Program& p, const std::string& type) {
  int n = 0;
  for (const Op& op : p.ops) n += op.spec->type == type;
  return n;
}

const std::string kColor = R"("tint": {"type": "vec3", "default": [0.5, 0.2, 1], "min": 0, "max": 1, "hint": "color"})";

void expectLinearOf(const Value& v, std::initializer_list<double> srgb) {
  int i = 0;
  for (double c : srgb) {
    EXPECT_NEAR(v[i], linear(c), 1e-15) << "component " << i;
    ++i;
  }
}

TEST(ColorParameters, AUniformColourIsLinearisedInTheShaderAndKeptInSrgbInTheManifest) {
  CompileResult r = compile(graphOf(kColor, "$tint"));
  std::string frag = fragmentOf(r);
  EXPECT_NE(frag.find("wg_srgb_to_linear_vec3(p_tint)"), std::string::npos) << frag;
  ASSERT_EQ(r.manifest.uniforms.size() > 0, true);
  const ManifestUniform* u = nullptr;
  for (const auto& m : r.manifest.uniforms)
    if (m.parameter && m.parameter->name == "tint") u = &m;
  ASSERT_TRUE(u);
  EXPECT_EQ(u->parameter->colorSpace, "srgb");
  EXPECT_EQ(u->parameter->defaultValue, (std::vector<double>{0.5, 0.2, 1}));  // as authored
  EXPECT_NE(r.manifest.fileText().find("\"color_space\": \"srgb\""), std::string::npos);
}

TEST(ColorParameters, AStaticColourFoldsToTheExactLinearConstant) {
  Program p = finalProgram(graphOf(R"("tint": {"type": "vec3", "default": [0.5, 0.2, 1], "hint": "color", "static": true})",
                                   "$tint"));
  EXPECT_EQ(opsOfType(p, "srgb_to_linear"), 0);
  const Op* shade = findOp(p, "shade");
  ASSERT_TRUE(shade);
  ASSERT_EQ(shade->inputs[0].kind, ValueRef::Kind::Const);
  expectLinearOf(shade->inputs[0].constant(), {0.5, 0.2, 1});
}

TEST(ColorParameters, EveryReadGoesThroughOneConversion) {
  Program p = resolveText(graphOf(kColor, "$tint", R"(, {"id": "again", "type": "add", "inputs": {"a": "$tint", "b": "$tint"}})"));
  EXPECT_EQ(opsOfType(p, "srgb_to_linear"), 1);
  const Op* again = findOp(p, "again");
  ASSERT_TRUE(again);
  EXPECT_EQ(again->inputs[0].kind, ValueRef::Kind::Op);
  EXPECT_EQ(p.ops[static_cast<size_t>(again->inputs[0].index)].spec->type, "srgb_to_linear");
  EXPECT_EQ(p.ops[static_cast<size_t>(again->inputs[0].index)].nodeId, "$tint");
}

TEST(ColorParameters, DataIsNeverConverted) {
  const std::string data = R"("wind": {"type": "vec3", "default": [0.5, 0.2, 1]})";
  EXPECT_EQ(opsOfType(resolveText(graphOf(data, "$wind")), "srgb_to_linear"), 0);
  std::string frag = fragmentOf(compile(graphOf(data, "$wind")));
  EXPECT_EQ(frag.find("srgb_to_linear"), std::string::npos) << frag;
  Program p = finalProgram(graphOf(R"("wind": {"type": "vec3", "default": [0.5, 0.2, 1], "static": true})", "$wind"));
  ASSERT_EQ(findOp(p, "shade")->inputs[0].kind, ValueRef::Kind::Const);
  EXPECT_EQ(findOp(p, "shade")->inputs[0].constant(), Value::vector({0.5, 0.2, 1}));
}

TEST(ColorParameters, AnHdrColourOfFourIsAcceptedAndContinuesThePowerSegment) {
  Program p = finalProgram(graphOf(R"("sun": {"type": "vec3", "default": [4, 1, 0.5], "hint": "hdr_color", "static": true})",
                                   "$sun"));
  const Op* shade = findOp(p, "shade");
  ASSERT_TRUE(shade);
  ASSERT_EQ(shade->inputs[0].kind, ValueRef::Kind::Const);
  EXPECT_NEAR(shade->inputs[0].constant()[0], std::pow(4.055 / 1.055, 2.4), 1e-12);
  expectLinearOf(shade->inputs[0].constant(), {4, 1, 0.5});
  std::string frag = fragmentOf(compile(graphOf(R"("sun": {"type": "vec3", "default": [4, 1, 0.5], "hint": "hdr_color"})", "$sun")));
  EXPECT_NE(frag.find("wg_srgb_to_linear_vec3(p_sun)"), std::string::npos) << frag;
}

TEST(ColorParameters, AVec4ColourKeepsItsAlpha) {
  Program p = finalProgram(graphJson(R"({"id": "s", "type": "swizzle", "options": {"mask": "w"}, "inputs": {"x": "$c"}})",
                                     R"("fragment": {"alpha": "s.out"})",
                                     R"("c": {"type": "vec4", "default": [0.5, 0.5, 0.5, 0.5], "hint": "color", "static": true})"));
  const ProgramOutput& alpha = outputOf(p, OutputSlot::FragmentAlpha);
  ASSERT_EQ(alpha.value.kind, ValueRef::Kind::Const);
  EXPECT_EQ(alpha.value.constant()[0], 0.5);
}

TEST(ColorParameters, ALiteralOnAColourPortIsLinearisedAndOnAnyOtherPortNot) {
  Program p = resolveText(graphJson(
      R"({"id": "tint", "type": "depth_tint", "inputs": {"shallow": [0.5, 0.5, 0.5], "depth": 1}},
         {"id": "m", "type": "mix", "inputs": {"a": "tint.color", "b": [0.5, 0.5, 0.5], "t": 0.5}},
         {"id": "a", "type": "absorption", "inputs": {"sigma": [0.5, 0.5, 0.5], "distance": 1}},
         {"id": "sum", "type": "add", "inputs": {"a": "m.out", "b": "a.transmittance"}})",
      R"("fragment": {"color": "sum.out"})"));
  const Op* tint = findOp(p, "tint");
  ASSERT_TRUE(tint);
  expectLinearOf(tint->inputs[static_cast<size_t>(tint->spec->inputIndex("shallow"))].constant(), {0.5, 0.5, 0.5});
  // The default of a colour port is sRGB-authored too: deep's (0, 0.1, 0.3).
  expectLinearOf(tint->inputs[static_cast<size_t>(tint->spec->inputIndex("deep"))].constant(), {0, 0.1, 0.3});
  // A literal on mix (no colour port) and absorption's coefficients (data) stay as written.
  EXPECT_EQ(findOp(p, "m")->inputs[1].constant(), Value::vector({0.5, 0.5, 0.5}));
  const Op* a = findOp(p, "a");
  EXPECT_EQ(a->inputs[static_cast<size_t>(a->spec->inputIndex("sigma"))].constant(), Value::vector({0.5, 0.5, 0.5}));
}

TEST(ColorParameters, ALiteralInTheColourSlotIsLinearised) {
  Program p = resolveText(graphJson("", R"("fragment": {"color": [0.5, 0.2, 1], "alpha": 0.5})"));
  expectLinearOf(outputOf(p, OutputSlot::FragmentColor).value.constant(), {0.5, 0.2, 1});
  EXPECT_EQ(outputOf(p, OutputSlot::FragmentAlpha).value.constant()[0], 0.5);
}

// An instance's colour input (a colour parameter of the function graph): a literal or the
// default is linearised once; a value wired from the user's colour parameter arrives
// linearised by the user's own conversion, not a second time.
TEST(ColorParameters, SubgraphColourInputsAreLinearisedOnce) {
  std::string dir = test::makeTempDir("wg_color_subgraph");
  test::writeFile(dir + "/lib.json", R"({"version": 1, "name": "lib",
    "interface": {"outputs": {"out": {"type": "vec3", "source": "pass.out"}}},
    "parameters": {"water": {"type": "vec3", "default": [0.5, 0.5, 0.5], "min": 0, "max": 1, "hint": "color"}},
    "nodes": [{"id": "pass", "type": "mul", "inputs": {"a": "$water", "b": 1}}]})");
  test::writeFile(dir + "/top.json", R"({"version": 1, "name": "top", "imports": {"lib": "lib.json"},
    "parameters": {"tint": {"type": "vec3", "default": [0.2, 0.2, 0.2], "hint": "color"}},
    "nodes": [{"id": "lit", "type": "lib", "inputs": {"water": [0.2, 0.3, 0.4]}},
              {"id": "def", "type": "lib"},
              {"id": "wired", "type": "lib", "inputs": {"water": "$tint"}},
              {"id": "s1", "type": "add", "inputs": {"a": "lit.out", "b": "def.out"}},
              {"id": "s2", "type": "add", "inputs": {"a": "s1.out", "b": "wired.out"}}],
    "outputs": {"fragment": {"color": "s2.out"}}})");
  Diagnostics diags;
  auto graph = loadGraphFile(dir + "/top.json", diags);
  ASSERT_TRUE(graph) << allText(diags);
  auto p = resolveGraph(*graph, defaultRegistry(), diags);
  ASSERT_TRUE(p) << allText(diags);
  expectLinearOf(findOp(*p, "lit/pass")->inputs[0].constant(), {0.2, 0.3, 0.4});
  expectLinearOf(findOp(*p, "def/pass")->inputs[0].constant(), {0.5, 0.5, 0.5});
  const Op* wired = findOp(*p, "wired/pass");
  ASSERT_EQ(wired->inputs[0].kind, ValueRef::Kind::Op);
  EXPECT_EQ(p->ops[static_cast<size_t>(wired->inputs[0].index)].nodeId, "$tint");
  EXPECT_EQ(opsOfType(*p, "srgb_to_linear"), 1);
}

}  // namespace color_parameters_test
}  // namespace wg
