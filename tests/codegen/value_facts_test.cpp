// Value facts (codegen/value_facts.h): what each source contributes, and that emitters
// choose an unguarded library variant only where the facts prove the guard dead — the
// same graph without the fact keeps the guarded form.
#include <gtest/gtest.h>

#include <cmath>

#include "codegen/compile.h"
#include "codegen/emit_glsl.h"
#include "codegen/passes.h"
#include "codegen/value_facts.h"
#include "core/graph_io.h"
#include "core/resolve.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg {
namespace {

using test::graphJson;

// Resolved and run through the compile recipe, as `watergraph compile` does.
Program compiledProgram(const std::string& json) {
  Diagnostics diags;
  auto graph = parseGraph(json, "test.json", diags);
  EXPECT_TRUE(graph);
  if (!graph) return {};
  auto program = buildProgram(*graph, defaultRegistry(), diags);
  EXPECT_TRUE(program);
  if (!program) return {};
  return std::move(*program);
}

std::string fragmentOf(const Program& p, EmitMode mode = EmitMode::Shader) {
  EmitResult r = emitProgram(p, Target::Glsl330, "test.json", mode);
  for (const auto& s : r.shaders)
    if (s.stage == ShaderStage::Fragment) return s.text;
  return "";
}

int opIndex(const Program& p, const std::string& id) {
  for (size_t i = 0; i < p.ops.size(); ++i)
    if (p.ops[i].nodeId == id) return static_cast<int>(i);
  return -1;
}

TEST(ValueFacts, SourcesGiveTheirFacts) {
  ValueFact unit = constantFact(Value::vector({0, 1, 0}));
  EXPECT_TRUE(unit.normalized);
  EXPECT_EQ(unit.lo, 0);
  EXPECT_EQ(unit.hi, 1);
  EXPECT_FALSE(constantFact(Value::vector({0, 2, 0})).normalized);
  EXPECT_TRUE(constantFact(Value::vector({0, 0, 0})).normalized);  // safe-normalising 0 gives 0
  EXPECT_FALSE(constantFact(Value::scalar(1)).normalized);          // a float is no direction
  EXPECT_TRUE(builtinFact(Builtin::ViewDirection).normalized);
  EXPECT_TRUE(builtinFact(Builtin::SunDirection).normalized);
  EXPECT_FALSE(builtinFact(Builtin::WorldPosition).normalized);
  EXPECT_EQ(builtinFact(Builtin::FragDepth).lo, 0);
  EXPECT_EQ(builtinFact(Builtin::FragDepth).hi, 1);
  EXPECT_EQ(builtinFact(Builtin::CameraNearFar).lo, 1e-6);

  Program p = compiledProgram(graphJson(
      R"({"id": "n", "type": "normal_map_scroll"},
         {"id": "f", "type": "fresnel", "inputs": {"normal": "n.normal", "strength": "$s"}},
         {"id": "w", "type": "world_position"},
         {"id": "m", "type": "mul", "inputs": {"a": "f.reflectance", "b": "w.out"}})",
      R"("fragment": {"color": "m.out"})", R"("s": {"type": "float", "default": 2, "min": 0.5, "max": 8})"));
  ValueFacts facts(p);
  // The normal_map_scroll op itself: its node also owns the ops of its derived scrolls.
  int n = -1;
  for (size_t i = 0; i < p.ops.size(); ++i)
    if (p.ops[i].nodeId == "n" && p.ops[i].spec->type == "normal_map_scroll") n = static_cast<int>(i);
  int f = opIndex(p, "f"), w = opIndex(p, "w");
  ASSERT_GE(n, 0);
  ASSERT_GE(f, 0);
  ASSERT_GE(w, 0);
  EXPECT_TRUE(facts.of(ValueRef::op(n, 0)).normalized);      // declared by normal_map_scroll
  EXPECT_EQ(facts.of(ValueRef::op(f, 0)).lo, 0);             // fresnel in [0, 1]
  EXPECT_EQ(facts.of(ValueRef::op(f, 0)).hi, 1);
  EXPECT_FALSE(facts.of(ValueRef::op(w, 0)).normalized);     // a position: nothing known
  EXPECT_TRUE(std::isinf(facts.of(ValueRef::op(w, 0)).hi));
  const Op& fresnel = p.ops[static_cast<size_t>(f)];
  ValueFact strength = facts.of(fresnel.inputs[static_cast<size_t>(fresnel.spec->inputIndex("strength"))]);
  EXPECT_EQ(strength.lo, 0.5);  // the parameter's min/max
  EXPECT_EQ(strength.hi, 8);
  // A float splat to a vector keeps its range but is no unit vector.
  EXPECT_FALSE(facts.of(ValueRef::constant_(Value::scalar(1)), Type::Vec3).normalized);
}

// Fresnel's power form: native pow only with a proven strength > 0.
TEST(ValueFacts, PowNeedsAProvenPositiveExponent) {
  auto graph = [](const std::string& param) {
    return compiledProgram(graphJson(
        R"({"id": "f", "type": "fresnel", "options": {"model": "power"}, "inputs": {"strength": "$s"}})",
        R"("fragment": {"alpha": "f.reflectance"})", R"("s": )" + param));
  };
  std::string proven = fragmentOf(graph(R"({"type": "float", "default": 2, "min": 0.1, "max": 10})"));
  EXPECT_NE(proven.find("wg_fresnel_power_cos_positive("), std::string::npos) << proven;
  for (const char* unproven : {R"({"type": "float", "default": 2})", R"({"type": "float", "default": 2, "min": 0})"}) {
    std::string s = fragmentOf(graph(unproven));
    EXPECT_EQ(s.find("_positive("), std::string::npos) << unproven;
    EXPECT_NE(s.find("wg_fresnel_power_cos("), std::string::npos) << s;
  }
  // Probe shaders take parameters from arbitrary cases: never the unguarded form.
  std::string probe = fragmentOf(graph(R"({"type": "float", "default": 2, "min": 0.1, "max": 10})"), EmitMode::Probe);
  EXPECT_EQ(probe.find("_positive("), std::string::npos);
}

// Phong: the unit lobe only when normal, view and light are all proven normalized. Both
// lobes are read (the colour): the environment's light (0, 1, 0) is unit, the default sun
// (1, 1, -0.5) is not, so one lobe of each form.
TEST(ValueFacts, PhongLobeSkipsRenormalisingOnlyUnitInputs) {
  std::string unit = fragmentOf(compiledProgram(graphJson(
      R"({"id": "p", "type": "phong_specular", "inputs": {"shine": "$k"}})", R"("fragment": {"color": "p.color"})",
      R"("k": {"type": "float", "default": 20, "min": 1, "max": 100})")));
  EXPECT_NE(unit.find("wg_phong_specular_lobe_unit(b_normal, b_view_direction, vec3(0.0, 1.0, 0.0))"), std::string::npos)
      << unit;
  EXPECT_NE(unit.find("wg_phong_specular_lobe(b_normal, b_view_direction, vec3(1.0, 1.0, -0.5))"), std::string::npos)
      << unit;
  EXPECT_NE(unit.find("wg_pow_known_safe_float("), std::string::npos) << unit;
  // A normal that is a world position is not unit; a shine without a range may be 0.
  std::string guarded = fragmentOf(compiledProgram(graphJson(
      R"({"id": "w", "type": "world_position"},
         {"id": "p", "type": "phong_specular", "inputs": {"normal": "w.out", "shine": "$k"}})",
      R"("fragment": {"alpha": "p.sun_specular"})", R"("k": {"type": "float", "default": 20})")));
  EXPECT_EQ(guarded.find("wg_phong_specular_lobe_unit("), std::string::npos) << guarded;
  EXPECT_NE(guarded.find("wg_phong_specular_lobe("), std::string::npos);
  EXPECT_EQ(guarded.find("wg_pow_known_safe_float("), std::string::npos);
}

// Remap: no empty-range select only when in_min and in_max cannot meet.
TEST(ValueFacts, RemapDropsTheEmptyRangeSelectOnlyForDisjointRanges) {
  auto remap = [](const std::string& param) {
    return fragmentOf(compiledProgram(graphJson(
        R"({"id": "t", "type": "time"},
           {"id": "r", "type": "remap", "options": {"clamp": true}, "inputs": {"x": "t.out", "in_min": 0, "in_max": "$b"}})",
        R"("fragment": {"alpha": "r.out"})", R"("b": )" + param)));
  };
  EXPECT_NE(remap(R"({"type": "float", "default": 1, "min": 0.01, "max": 5})").find("wg_remap_clamped_nonempty_float("),
            std::string::npos);
  std::string touching = remap(R"({"type": "float", "default": 1, "min": 0, "max": 5})");  // b may equal a
  EXPECT_EQ(touching.find("_nonempty"), std::string::npos) << touching;
  EXPECT_NE(touching.find("wg_remap_clamped_float("), std::string::npos) << touching;
}

// Found in review: a bound that only holds in double must not count. The shader sees the
// float nearest each bound (0.10000000001 is 0.1f, equal to the literal 0.1), and a float
// denormal bound may be flushed to zero on the GPU.
TEST(ValueFacts, BoundsAreTheFloatsTheShaderSees) {
  auto remap = [](const std::string& min) {
    return fragmentOf(compiledProgram(graphJson(
        R"({"id": "t", "type": "time"},
           {"id": "r", "type": "remap", "inputs": {"x": "t.out", "in_min": 0.1, "in_max": "$b"}})",
        R"("fragment": {"alpha": "r.out"})", R"("b": {"type": "float", "default": 0.5, "min": )" + min + ", \"max\": 1}")));
  };
  std::string rounded = remap("0.10000000001");
  EXPECT_EQ(rounded.find("_nonempty"), std::string::npos) << rounded;
  EXPECT_NE(remap("0.1000001").find("wg_remap_nonempty_float("), std::string::npos);  // a float apart

  auto fresnelPower = [](const std::string& min) {
    return fragmentOf(compiledProgram(graphJson(
        R"({"id": "f", "type": "fresnel", "options": {"model": "power"}, "inputs": {"strength": "$s"}})",
        R"("fragment": {"alpha": "f.reflectance"})", R"("s": {"type": "float", "default": 1, "min": )" + min + ", \"max\": 10}")));
  };
  std::string denormal = fresnelPower("1e-50");
  EXPECT_EQ(denormal.find("_positive"), std::string::npos) << denormal;
  EXPECT_NE(fresnelPower("1e-30").find("wg_fresnel_power_cos_positive("), std::string::npos);
}

// Found in review: a node's output range may depend on its inputs. Fresnel is in [0, 1]
// only for f0 in [0, 1] (schlick) or strength >= 0 (power); phong's sun term only for
// shine >= 0. Outside them a consumer must keep its guard.
TEST(ValueFacts, OutputRangesHoldOnlyForInputsThatKeepThem) {
  auto powOfTransmittance = [](const std::string& fresnel) {
    return fragmentOf(compiledProgram(graphJson(
        R"({"id": "f", "type": "fresnel", )" + fresnel + R"(},
           {"id": "p", "type": "pow", "inputs": {"x": "f.transmittance", "y": 2.0}})",
        R"("fragment": {"alpha": "p.out"})")));
  };
  EXPECT_NE(powOfTransmittance(R"("options": {"model": "schlick"}, "inputs": {"f0": 0.02})").find("wg_pow_known_safe_float("),
            std::string::npos);
  std::string f0 = powOfTransmittance(R"("options": {"model": "schlick"}, "inputs": {"f0": 2.0})");
  EXPECT_EQ(f0.find("wg_pow_known_safe_float("), std::string::npos) << f0;
  std::string negative = powOfTransmittance(R"("options": {"model": "power"}, "inputs": {"strength": -1.0})");
  EXPECT_EQ(negative.find("wg_pow_known_safe_float("), std::string::npos) << negative;

  auto remapOfSun = [](double shine) {
    return fragmentOf(compiledProgram(graphJson(
        R"({"id": "p", "type": "phong_specular", "inputs": {"shine": )" + std::to_string(shine) + R"(}},
           {"id": "r", "type": "remap", "inputs": {"x": 1.0, "in_min": "p.sun_specular", "in_max": 2.0}})",
        R"("fragment": {"alpha": "r.out"})")));
  };
  EXPECT_NE(remapOfSun(20).find("wg_remap_nonempty_float("), std::string::npos);
  std::string shine = remapOfSun(-1);
  EXPECT_EQ(shine.find("_nonempty"), std::string::npos) << shine;
}

// The math vocabulary: each guarded form gives way to the raw built-in only where the
// facts of its input make the guard dead, and stays where they do not.
TEST(ValueFacts, VocabularyPicksTheRawBuiltinOnlyWhereItsGuardIsDead) {
  auto unary = [](const std::string& type, const std::string& param) {
    return fragmentOf(compiledProgram(graphJson(R"({"id": "f", "type": ")" + type + R"(", "inputs": {"x": "$p"}})",
                                                R"("fragment": {"alpha": "f.out"})", R"("p": )" + param)));
  };
  struct Expect {
    const char* type;
    const char* raw;       // the built-in call
    const char* guarded;   // the library call
    const char* provenSafe;
    const char* unproven;
  };
  const char* positive = R"({"type": "float", "default": 2, "min": 0.001, "max": 50})";
  const char* any = R"({"type": "float", "default": 2})";
  for (const Expect& e : std::vector<Expect>{
           {"log", " log(", "wg_safe_log_float(", positive, R"({"type": "float", "default": 2, "min": 0})"},
           {"log2", " log2(", "wg_safe_log2_float(", positive, any},
           {"sqrt", " sqrt(", "wg_safe_sqrt_float(", R"({"type": "float", "default": 2, "min": 0})", any},
           {"inversesqrt", " inversesqrt(", "wg_safe_inversesqrt_float(", positive, any},
           {"exp", " exp(", "wg_safe_exp_float(", positive, R"({"type": "float", "default": 2, "max": 100})"},
           {"exp2", " exp2(", "wg_safe_exp2_float(", positive, R"({"type": "float", "default": 2, "max": 200})"},
           {"asin", " asin(", "wg_safe_asin_float(", R"({"type": "float", "default": 0.5, "min": -1, "max": 1})", any},
           {"acos", " acos(", "wg_safe_acos_float(", R"({"type": "float", "default": 0.5, "min": -1, "max": 1})",
            R"({"type": "float", "default": 0.5, "min": -1, "max": 1.0000001})"},
           {"tan", " tan(", "wg_safe_tan_float(", R"({"type": "float", "default": 0.5, "min": -1, "max": 1})",
            R"({"type": "float", "default": 0.5, "min": -1, "max": 2})"},
           {"sinh", " sinh(", "wg_safe_sinh_float(", positive, any},
           {"tanh", " tanh(", "wg_safe_tanh_float(", R"({"type": "float", "default": 0.5, "min": -10, "max": 10})", R"({"type": "float", "default": 0.5, "min": 0, "max": 11})"}}) {
    SCOPED_TRACE(e.type);
    std::string proven = unary(e.type, e.provenSafe), unproven = unary(e.type, e.unproven);
    EXPECT_NE(proven.find(e.raw), std::string::npos) << proven;
    EXPECT_EQ(proven.find(e.guarded), std::string::npos) << proven;
    EXPECT_NE(unproven.find(e.guarded), std::string::npos) << unproven;
  }
  // Facts flow through the vocabulary: sqrt of a fract is raw (fract lies in [0, 1]); a
  // mod by 1 cannot overflow its quotient; atan of a point with x > 0 is never the origin.
  std::string chained = fragmentOf(compiledProgram(graphJson(
      R"({"id": "t", "type": "time"}, {"id": "f", "type": "fract", "inputs": {"x": "t.out"}},
         {"id": "r", "type": "sqrt", "inputs": {"x": "f.out"}},
         {"id": "m", "type": "mod", "inputs": {"x": "t.out", "y": 1.0}},
         {"id": "a", "type": "atan2", "inputs": {"y": "t.out", "x": 2.0}},
         {"id": "s1", "type": "add", "inputs": {"a": "r.out", "b": "m.out"}},
         {"id": "s2", "type": "add", "inputs": {"a": "s1.out", "b": "a.out"}})",
      R"("fragment": {"alpha": "s2.out"})")));
  EXPECT_EQ(chained.find("wg_safe_sqrt"), std::string::npos) << chained;
  EXPECT_EQ(chained.find("wg_safe_mod"), std::string::npos) << chained;
  EXPECT_EQ(chained.find("wg_safe_atan2"), std::string::npos) << chained;
  std::string unknown = fragmentOf(compiledProgram(graphJson(
      R"({"id": "t", "type": "time"}, {"id": "w", "type": "world_position"},
         {"id": "r", "type": "sqrt", "inputs": {"x": "w.out"}},
         {"id": "m", "type": "mod", "inputs": {"x": "t.out", "y": "w.out"}},
         {"id": "s1", "type": "add", "inputs": {"a": "r.out", "b": "m.out"}})",
      R"("fragment": {"color": "s1.out"})")));
  EXPECT_NE(unknown.find("wg_safe_sqrt_vec3("), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("wg_safe_mod_vec3("), std::string::npos) << unknown;
}

// saturate and clamp: dead where the input already lies within the bounds (screen_uv is in
// [0, 1]), and their output ranges feed later guards; bounds that may be reversed (GLSL
// leaves clamp undefined there) do not give a range they would break.
TEST(ValueFacts, ClampIsDeadWhereTheInputKeepsItsBounds) {
  auto alpha = [](const std::string& nodes, const std::string& out, const std::string& params = "") {
    return fragmentOf(compiledProgram(graphJson(nodes, R"("fragment": {"alpha": ")" + out + R"("})", params)));
  };
  std::string screen = alpha(R"({"id": "u", "type": "screen_uv"}, {"id": "s", "type": "saturate", "inputs": {"x": "u.out"}},
                                 {"id": "x", "type": "swizzle", "options": {"mask": "x"}, "inputs": {"x": "s.out"}})",
                             "x.out");
  EXPECT_EQ(screen.find("clamp("), std::string::npos) << screen;
  std::string world = alpha(R"({"id": "w", "type": "world_position"}, {"id": "s", "type": "saturate", "inputs": {"x": "w.out"}},
                                {"id": "x", "type": "swizzle", "options": {"mask": "x"}, "inputs": {"x": "s.out"}})",
                            "x.out");
  EXPECT_NE(world.find("clamp("), std::string::npos) << world;
  // clamp(fract(t), 0, 2) is dead; clamp(fract(t), 0.5, 2) is not.
  for (auto [lo, dead] : {std::pair{"0.0", true}, std::pair{"0.5", false}}) {
    std::string s = alpha(std::string(R"({"id": "t", "type": "time"}, {"id": "f", "type": "fract", "inputs": {"x": "t.out"}},
                                         {"id": "c", "type": "clamp", "inputs": {"x": "f.out", "lo": )") + lo + R"(, "hi": 2.0}})",
                          "c.out");
    EXPECT_EQ(s.find("clamp(") == std::string::npos, dead) << s;
  }
  // The range reaches the next guard: sqrt of saturate(t) is the raw built-in.
  std::string sqrtOfSaturate = alpha(R"({"id": "t", "type": "time"}, {"id": "s", "type": "saturate", "inputs": {"x": "t.out"}},
                                         {"id": "r", "type": "sqrt", "inputs": {"x": "s.out"}})",
                                     "r.out");
  EXPECT_EQ(sqrtOfSaturate.find("wg_safe_sqrt"), std::string::npos) << sqrtOfSaturate;
  EXPECT_NE(sqrtOfSaturate.find(" sqrt("), std::string::npos) << sqrtOfSaturate;
  // lo in [0, 0.5] and hi in [-1, 1] may be reversed: the clamp may give hi = -1, so the
  // square root keeps its guard; with hi in [0.5, 1] it cannot.
  for (auto [hiMin, guarded] : {std::pair{"-1", true}, std::pair{"0.5", false}}) {
    std::string s = alpha(R"({"id": "t", "type": "time"}, {"id": "c", "type": "clamp", "inputs": {"x": "t.out", "lo": "$a", "hi": "$b"}},
                             {"id": "r", "type": "sqrt", "inputs": {"x": "c.out"}})",
                          "r.out",
                          std::string(R"("a": {"type": "float", "default": 0, "min": 0, "max": 0.5}, "b": {"type": "float", "default": 1, "min": )") +
                              hiMin + R"(, "max": 1})");
    EXPECT_EQ(s.find("wg_safe_sqrt_float(") != std::string::npos, guarded) << s;
  }
}

}  // namespace
}  // namespace wg
