// GlslExpr (core/emit_context.h): the values a node's emit builds carry what they read and
// call, and how many operations they ask for, through every concatenation, so the planner
// can decide and count from them instead of from the text.
#include <gtest/gtest.h>

#include "core/emit_context.h"

namespace wg {
namespace {

std::vector<uint32_t> symbolsOf(const GlslExpr& e) { return {e.symbols().begin(), e.symbols().end()}; }

TEST(GlslExpr, ConcatenationKeepsWhatEachPartReadsOnce) {
  GlslExpr a = GlslExpr::symbol("n1_t0", 7);
  GlslExpr b = GlslExpr::symbol("p_x", 9);
  GlslExpr e = "(" + a + " * " + b + " + " + a + ")";
  EXPECT_EQ(e.text(), "(n1_t0 * p_x + n1_t0)");
  EXPECT_EQ(symbolsOf(e), (std::vector<uint32_t>{7, 9}));
  GlslExpr grown;
  grown += b;
  grown += std::string(" - ");
  grown += a;
  EXPECT_EQ(grown.text(), "p_x - n1_t0");
  EXPECT_EQ(symbolsOf(grown), (std::vector<uint32_t>{9, 7}));
}

TEST(GlslExpr, OnlyOnePieceThatIsANameIsOne) {
  EXPECT_TRUE(GlslExpr::symbol("n1_t0", 1).isName());
  EXPECT_TRUE(GlslExpr::name("v_uv").isName());
  EXPECT_FALSE(GlslExpr("b_water_surface.w").isName());  // text reads as text, never as a name
  EXPECT_FALSE(GlslExpr("1.0").isName());
  EXPECT_FALSE((GlslExpr::name("v_uv") + ".x").isName());
  GlslExpr e;
  e += GlslExpr::name("v_uv");
  EXPECT_TRUE(e.isName());  // appended to nothing, it is what it was
  e += "";
  EXPECT_TRUE(e.isName());
  e += GlslExpr::name("v_normal");
  EXPECT_FALSE(e.isName());
}

TEST(GlslExpr, CallRecordsTheFunctionAndWhatItsArgumentsCall) {
  GlslExpr inner = EmitContext::call("wg_safe_normalize_vec3", {GlslExpr::symbol("b_normal", 3)});
  GlslExpr outer = EmitContext::call("wg_fresnel_schlick", {inner, "0.02", inner});
  EXPECT_EQ(outer.text(), "wg_fresnel_schlick(wg_safe_normalize_vec3(b_normal), 0.02, wg_safe_normalize_vec3(b_normal))");
  EXPECT_EQ(outer.calls(), (std::vector<std::string>{"wg_safe_normalize_vec3", "wg_fresnel_schlick"}));
  EXPECT_EQ(symbolsOf(outer), (std::vector<uint32_t>{3}));
  EXPECT_FALSE(outer.isName());
  // A name written by hand is no call: nothing records it.
  EXPECT_TRUE(GlslExpr("wg_safe_normalize_vec3(x)").calls().empty());
}

TEST(GlslExpr, ManySymbolsStayEachOnceInOrder) {
  GlslExpr e;
  for (uint32_t round = 0; round < 2; ++round)
    for (uint32_t s = 0; s < 9; ++s) e += GlslExpr::symbol("a", s) + " + ";  // past the inline four
  EXPECT_EQ(symbolsOf(e), (std::vector<uint32_t>{0, 1, 2, 3, 4, 5, 6, 7, 8}));
}

// The counting rules (core/glsl_operation_count.h), on pieces a node writes.
TEST(GlslExprOperations, CountsOperatorsAndCallsNotSignsConstructorsOrComments) {
  EXPECT_EQ(GlslExpr("a + b * c").operations(), 2);
  EXPECT_EQ(GlslExpr("-x * 2.0").operations(), 1) << "a unary minus is free";
  EXPECT_EQ(GlslExpr("max(x, 1e-30) - 1.5e+3").operations(), 2) << "an exponent's sign is no subtraction";
  EXPECT_EQ(GlslExpr("vec3(a, b.xy)").operations(), 0) << "constructors and swizzles are free";
  EXPECT_EQ(GlslExpr("float y = x < 0.5 ? a : b;").operations(), 2);
  EXPECT_EQ(GlslExpr("a // b + c\n").operations(), 0) << "comments are skipped";
  EXPECT_EQ(GlslExpr("texture(s, uv).rgb").operations(), 1);
  EXPECT_EQ(GlslExpr("a == b && c != d").operations(), 3);
}

// A count continues across the pieces and values it is built from: the same text counts
// the same however it was cut.
TEST(GlslExprOperations, TheSeamsBetweenPiecesAndValuesCountAsTheWholeText) {
  const GlslExpr x = GlslExpr::name("x"), y = GlslExpr::name("y");
  EXPECT_EQ(("(" + x + " - " + y + ")").operations(), 1);
  EXPECT_EQ((GlslExpr("(") + "-" + x + ")").operations(), 0) << "a sign after '(' stays a sign";
  EXPECT_EQ((x + " " + GlslExpr("-0.5")).operations(), 1) << "a value's leading sign after an operand is a subtraction";
  EXPECT_EQ((x + " * " + GlslExpr("-0.5")).operations(), 1) << "and after an operator a sign";
  EXPECT_EQ((GlslExpr("max") + "(" + x + ", " + y + ")").operations(), 1) << "a name that ends a piece is called by the next";
  EXPECT_EQ((GlslExpr("vec3") + "(" + x + ")").operations(), 0) << "a constructor split from its parenthesis";
  EXPECT_EQ((GlslExpr("max") + GlslExpr("(x, y)")).operations(), 1) << "a value that opens the call";
  EXPECT_EQ((GlslExpr("b") + " " + GlslExpr("+ c")).operations(), 1);
  // A value appended brings its own count; the names never count.
  GlslExpr product = "(" + x + " * " + y + ")";
  EXPECT_EQ((product + " + " + product).operations(), 3);
}

TEST(GlslExprOperations, ACallCostsItsFunctionAndItsArguments) {
  const GlslExpr x = GlslExpr::name("x");
  EXPECT_EQ(EmitContext::call("sin", {x}).operations(), 1) << "a GLSL built-in";
  EXPECT_EQ(EmitContext::call("vec3", {x, x, x}).operations(), 0) << "a constructor";
  EXPECT_EQ(EmitContext::call("clamp", {x + " * 2.0", "0.0", "1.0"}).operations(), 2);
  EXPECT_EQ(EmitContext::call("sin", {EmitContext::call("cos", {x})}).operations(), 2);
  EXPECT_EQ(("1.0 - " + EmitContext::call("sin", {x})).operations(), 2);
}

// Names are operands whose text is never read: another name, the same count.
TEST(GlslExprOperations, NamesNeverCount) {
  for (const char* name : {"a", "p_wave_gain", "n_final_shade_t0", "gl_FragCoord.xy", "texture"}) {
    SCOPED_TRACE(name);
    const GlslExpr n = GlslExpr::name(name), s = GlslExpr::symbol(name, 3);
    EXPECT_EQ(n.operations(), 0);
    EXPECT_EQ(("(" + n + " * " + s + ")").operations(), 1);
    EXPECT_EQ(EmitContext::call("wg_safe_normalize_vec3", {n}).operations(),
              EmitContext::call("wg_safe_normalize_vec3", {GlslExpr::name("v")}).operations());
  }
}

}  // namespace
}  // namespace wg
