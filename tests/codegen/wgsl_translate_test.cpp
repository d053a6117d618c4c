// The GLSL subset printed as WGSL (codegen/wgsl_translate.h): each rule WGSL adds over GLSL
// is kept by construction, and every item of the library translates in both stages. naga's
// verdict on the output is tests/ecosystem/wgsl_naga_test.cpp's.
#include <gtest/gtest.h>

#include <stdexcept>

#include "codegen/wgsl_translate.h"
#include "nodes/glsl_library.h"

namespace wg {
namespace {

using wgsl::StageMode;
using wgsl::Translator;
using wgsl::ValueType;

// One library-like item translated in `mode`; the module's functions.
std::string translatedItem(const std::string& glsl, StageMode mode = StageMode::Fragment) {
  Translator t;
  t.addItem(GlslItem{"wg_test_item", "test", glsl, {}}, mode);
  return t.functionsText();
}

TEST(WgslTranslate, ScalarsBesideVectorsAreSplattedWhereGlslWidensThem) {
  std::string w = translatedItem("vec3 wg_t(vec3 v) { return clamp(v, 0.0, 1.0) + step(0.5, v) + max(v, 2.0); }");
  EXPECT_NE(w.find("clamp(v, vec3<f32>(0.0), vec3<f32>(1.0))"), std::string::npos) << w;
  EXPECT_NE(w.find("step(vec3<f32>(0.5), v)"), std::string::npos) << w;
  EXPECT_NE(w.find("max(v, vec3<f32>(2.0))"), std::string::npos) << w;
}

// Built-ins WGSL spells otherwise (Tint rejected `faceforward`, found by `probe --target wgsl`).
TEST(WgslTranslate, BuiltinsWgslSpellsOtherwiseAreRenamed) {
  std::string w = translatedItem("vec3 wg_t(vec3 n, vec3 i, float x) { return faceforward(n, i, n) * inversesqrt(x); }");
  EXPECT_NE(w.find("faceForward(n, i, n) * inverseSqrt(x)"), std::string::npos) << w;
}

TEST(WgslTranslate, VectorEqualityIsReducedAndTernaryIsSelect) {
  std::string w = translatedItem("float wg_t(vec2 a, vec2 b) { return a == b ? 1.0 : 0.0; }");
  EXPECT_NE(w.find("select(0.0, 1.0, all(a == b))"), std::string::npos) << w;
}

TEST(WgslTranslate, MixWithABoolSelectorIsSelect) {
  // Found by naga and Tint checking the whole library: WGSL's mix takes no bool vector.
  std::string w = translatedItem("vec2 wg_t(vec2 a, vec2 b, vec2 x) { return mix(a, b, lessThan(x, a)); }");
  EXPECT_NE(w.find("return select(a, b, (x < a));"), std::string::npos) << w;
}

TEST(WgslTranslate, ModIsGlslsFloorDefinitionNotWgslsTruncatingPercent) {
  std::string w = translatedItem("vec2 wg_t(vec2 x) { return mod(x, 3.0); }");
  EXPECT_NE(w.find("wgsl_mod_vec2f(x, vec2<f32>(3.0))"), std::string::npos) << w;
  EXPECT_NE(w.find("fn wgsl_mod_vec2f(x: vec2<f32>, y: vec2<f32>) -> vec2<f32> { return x - y * floor(x / y); }"),
            std::string::npos)
      << w;
}

TEST(WgslTranslate, MatrixConstructorsWgslLacks) {
  std::string w = translatedItem("mat3 wg_t(mat4 m) { return mat3(m) + mat3(0.0); }");
  EXPECT_NE(w.find("mat3x3<f32>(m[0].xyz, m[1].xyz, m[2].xyz)"), std::string::npos) << w;
  EXPECT_NE(w.find("mat3x3<f32>(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)"), std::string::npos) << w;
}

TEST(WgslTranslate, ShiftCountsBecomeU32AndSplatForVectors) {
  std::string w = translatedItem("uvec2 wg_t(uvec2 v, int s) { return v >> s; }");
  EXPECT_NE(w.find("(v >> vec2<u32>(u32(s)))"), std::string::npos) << w;
}

TEST(WgslTranslate, ReservedWordsAreRenamedAndAssignedParametersCopied) {
  std::string w = translatedItem("float wg_t(float target, float filter) { target += filter; return target; }");
  EXPECT_NE(w.find("fn wg_t(target__in: f32, filter_: f32) -> f32"), std::string::npos) << w;
  EXPECT_NE(w.find("var target_: f32 = target__in;"), std::string::npos) << w;
  EXPECT_NE(w.find("target_ += filter_;"), std::string::npos) << w;
}

TEST(WgslTranslate, ImplicitLodSamplesOnlyUnderUniformControlFlowOfTheFragmentStage) {
  const std::string glsl =
      "float wg_t(sampler2D tex, vec2 uv, int n) {\n"
      "  float a = texture(tex, uv).x;\n"
      "  for (int i = 0; i < n; ++i) { a += texture(tex, uv).x; }\n"
      "  return a;\n"
      "}\n";
  std::string frag = translatedItem(glsl, StageMode::Fragment);
  // Before the loop: implicit LOD; inside it: level 0.
  size_t loop = frag.find("for (");
  ASSERT_NE(loop, std::string::npos) << frag;
  EXPECT_LT(frag.find("textureSample(tex_texture, tex_sampler, uv)"), loop) << frag;
  EXPECT_GT(frag.find("textureSampleLevel(tex_texture, tex_sampler, uv, 0.0)"), loop) << frag;
  // It samples with an implicit LOD, so it also has its level-0 form, for the vertex stage.
  EXPECT_NE(frag.find("fn wg_t_lod0("), std::string::npos) << frag;
  std::string vert = translatedItem(glsl, StageMode::Vertex);
  EXPECT_EQ(vert.find("textureSample("), std::string::npos) << vert;
  EXPECT_NE(vert.find("fn wg_t_lod0("), std::string::npos) << vert;
}

TEST(WgslTranslate, ASamplingFunctionCalledInALoopIsCalledInItsLevelZeroForm) {
  Translator t;
  t.addItem(GlslItem{"wg_s", "test", "float wg_s(sampler2D tex, vec2 uv) { return texture(tex, uv).x; }", {}},
            StageMode::Fragment);
  t.addItem(GlslItem{"wg_u", "test",
                     "float wg_u(sampler2D tex, vec2 uv) {\n  float a = wg_s(tex, uv);\n"
                     "  for (int i = 0; i < 2; ++i) a += wg_s(tex, uv);\n  return a;\n}\n",
                     {"wg_s"}},
            StageMode::Fragment);
  std::string w = t.functionsText();
  EXPECT_NE(w.find("var a: f32 = wg_s(tex_texture, tex_sampler, uv);"), std::string::npos) << w;
  EXPECT_NE(w.find("a += wg_s_lod0(tex_texture, tex_sampler, uv);"), std::string::npos) << w;
}

// A planned expression reads the globals through their WGSL names and the locals declared
// before it with the types the plan gave them; an assignment goes to a declared name, its
// value of that name's type.
TEST(WgslTranslate, PlannedExpressionsReadGlobalsAndDeclaredLocals) {
  Translator t;
  t.declareGlobal("u_time", ValueType{'f', 1, 0}, "wg_u.u_time");
  t.declareGlobal("v_uv", ValueType{'f', 2, 0}, "wg_out.v_uv");
  t.declareSampler("t0_foam", ValueType{'t', 1, 0}, "t0_foam", "t0_foam_sampler");
  EXPECT_EQ(t.expression("u_time * 2.0", StageMode::Fragment, {'f', 1, 0}), "(wg_u.u_time * 2.0)");
  EXPECT_THROW(t.expression("n1_a", StageMode::Fragment, {'f', 1, 0}), std::logic_error) << "not declared yet";
  EXPECT_EQ(t.declareLocal("n1_a", {'f', 1, 0}), "n1_a");
  EXPECT_EQ(t.expression("texture(t0_foam, vec2(n1_a))", StageMode::Fragment, {'f', 4, 0}),
            "textureSample(t0_foam, t0_foam_sampler, vec2<f32>(n1_a))");
  EXPECT_EQ(t.expression("texture(t0_foam, vec2(n1_a))", StageMode::Vertex, {'f', 4, 0}),
            "textureSampleLevel(t0_foam, t0_foam_sampler, vec2<f32>(n1_a), 0.0)");
  // The type is the plan's: a local declared a vec3 is read as one.
  t.declareLocal("n2_b", {'f', 3, 0});
  EXPECT_EQ(t.expression("n2_b.xy", StageMode::Fragment, {'f', 2, 0}), "n2_b.xy");
  EXPECT_THROW(t.expression("n2_b", StageMode::Fragment, {'f', 2, 0}), std::logic_error);
  EXPECT_EQ(t.assignment("v_uv", "n2_b.xy", StageMode::Vertex), "wg_out.v_uv = n2_b.xy");
  EXPECT_THROW(t.assignment("v_uv", "n2_b", StageMode::Vertex), std::logic_error) << "a vec3 into a vec2";
  EXPECT_THROW(t.assignment("v_undeclared", "n2_b", StageMode::Vertex), std::logic_error);
  // A WGSL keyword as a local's name is renamed where it is declared and where it is read.
  EXPECT_EQ(t.declareLocal("loop", {'f', 1, 0}), "loop_");
  EXPECT_EQ(t.expression("loop + 1.0", StageMode::Fragment, {'f', 1, 0}), "(loop_ + 1.0)");
  // The next entry point starts with no locals.
  t.clearLocals();
  EXPECT_THROW(t.expression("n1_a", StageMode::Fragment, {'f', 1, 0}), std::logic_error);
  // One expression and nothing after it.
  EXPECT_THROW(t.expression("u_time; u_time", StageMode::Fragment, {'f', 1, 0}), std::logic_error);
}

TEST(WgslTranslate, ConstructsOutsideTheSubsetAreRefusedNotGuessed) {
  EXPECT_THROW(translatedItem("void wg_t(out float x) { x = 1.0; }"), std::logic_error);
  EXPECT_THROW(translatedItem("float wg_t(vec3 v) { v.xy = vec2(0.0); return v.x; }"), std::logic_error);
  EXPECT_THROW(translatedItem("#define X 1\nfloat wg_t() { return 1.0; }"), std::logic_error);
  Translator t;
  EXPECT_THROW(t.expression("unknown_name", StageMode::Fragment, {'f', 1, 0}), std::logic_error);
  EXPECT_THROW(t.expression("7.0 % 2.0", StageMode::Fragment, {'f', 1, 0}), std::logic_error);
}

// Every item of the embedded library, dependencies first, in both stages: none is outside the
// subset (naga validates the same text in tests/ecosystem/wgsl_naga_test.cpp).
TEST(WgslTranslate, EveryLibraryItemTranslatesInBothStages) {
  const GlslLibrary& lib = GlslLibrary::builtin();
  ASSERT_GT(lib.items().size(), 100u);
  for (StageMode mode : {StageMode::Vertex, StageMode::Fragment}) {
    Translator t;
    for (const GlslItem& item : lib.items())
      for (const GlslItem* needed : lib.itemsNamed({item.name})) EXPECT_NO_THROW(t.addItem(*needed, mode)) << needed->name;
    std::string w = t.functionsText();
    for (const GlslItem& item : lib.items()) EXPECT_NE(w.find(item.name), std::string::npos) << item.name;
  }
}

}  // namespace
}  // namespace wg
