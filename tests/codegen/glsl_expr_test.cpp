// GlslExpr (core/emit_context.h): the values a node's emit builds carry what they read and
// call through every concatenation, so the planner can decide from them instead of from
// the text.
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

}  // namespace
}  // namespace wg
