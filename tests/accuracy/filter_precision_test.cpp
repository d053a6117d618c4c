// The filter-precision part of check's error bound (accuracy/error_bound.h): each node
// texture look-up the reference filters itself moves, one at a time, by its
// filterUncertainty (nodes/texture_sampling.h). No GPU.
#include <gtest/gtest.h>

#include "accuracy/error_bound.h"
#include "accuracy/fragment_program.h"
#include "codegen/cpu_backend.h"
#include "compile_text.h"
#include "nodes/texture_sampling.h"
#include "nodes/texture_source.h"

namespace wg::accuracy {
namespace {

Program fragmentOf(const std::string& json) { return fragmentProgram(test::compileText(json).program).program; }

// One bilinear look-up of the height map, its red channel the colour: the term grows by
// exactly that look-up's uncertainty, and an evaluation with a nudge counts the look-up.
TEST(FilterPrecision, OneLookUpAddsItsUncertainty) {
  Program p = fragmentOf(R"({"version": 1, "name": "t", "nodes": [
      {"id": "t", "type": "texture_sample", "options": {"texture": "builtin:height", "color_space": "linear"}},
      {"id": "r", "type": "swizzle", "options": {"mask": "xxx"}, "inputs": {"x": "t.rgb"}}],
    "outputs": {"fragment": {"color": "r.out"}}})");
  EvalEnvironment env;
  env.uv = Value::vector({0.3137, 0.7071});
  FilterNudge count;
  evaluateProgram(p, env, {}, nullptr, &count);
  EXPECT_EQ(count.count, 1);

  std::string why;
  auto image = loadTexture("builtin:height", "", &why);
  ASSERT_TRUE(image) << why;
  SamplerState state;  // repeat, linear, and linear data as the options above
  const double delta = filterUncertainty(*image, 0.3137, 0.7071, state);
  ASSERT_GT(delta, std::ldexp(1.0, -9));  // a footprint with some spread

  auto without = conditioningTerm(p, env, {}, {}, 1.0, nullptr, false);
  auto with = conditioningTerm(p, env, {}, {}, 1.0, nullptr, true);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(with[static_cast<size_t>(c)] - without[static_cast<size_t>(c)], delta, 1e-12) << c;
}

// A nudge changes only the look-up it names: one of the two alphas moves, the other not.
TEST(FilterPrecision, ANudgeMovesOnlyTheLookUpItNames) {
  Program p = fragmentOf(R"({"version": 1, "name": "t", "nodes": [
      {"id": "a", "type": "texture_sample", "options": {"texture": "builtin:height", "color_space": "linear"}},
      {"id": "uv2", "type": "mul", "inputs": {"a": "$uv_scale", "b": 0.5}},
      {"id": "b", "type": "texture_sample", "options": {"texture": "builtin:foam", "color_space": "linear"},
       "inputs": {"uv": "uv2.out"}},
      {"id": "out", "type": "combine", "inputs": {"x": "a.alpha", "y": "b.alpha", "z": 0}}],
    "parameters": {"uv_scale": {"type": "vec2", "default": [0.4, 0.6]}},
    "outputs": {"fragment": {"color": "out.out"}}})");
  EvalEnvironment env;
  Value base = evaluateProgram(p, env).outputs.front();
  FilterNudge nudge;
  nudge.nudged = 1;
  nudge.fraction = 1.0;
  Value moved = evaluateProgram(p, env, {}, nullptr, &nudge).outputs.front();
  EXPECT_EQ(nudge.count, 2);
  EXPECT_NE(moved[0] == base[0], moved[1] == base[1]) << moved[0] << " " << moved[1];
  EXPECT_GE(moved[0], base[0]);
  EXPECT_GE(moved[1], base[1]);
}

}  // namespace
}  // namespace wg::accuracy
