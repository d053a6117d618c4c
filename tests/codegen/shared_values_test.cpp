// Resolve holds equal options and equal constants once (core/interned_values.h), and
// keeps apart what only looks equal: -0.0 is not 0.0 (1 / x tells them apart, and cse
// compares constants bit by bit).
#include <gtest/gtest.h>

#include "core/interned_values.h"
#include "pass_test_support.h"

namespace wg {
namespace {

using namespace passtest;

TEST(SharedValues, EqualOptionsAndConstantsAreHeldOnce) {
  Program p = resolveText(graphJson(
      R"({"id": "u", "type": "uv"},
         {"id": "a", "type": "swizzle", "options": {"mask": "yx"}, "inputs": {"x": "u.out"}},
         {"id": "b", "type": "swizzle", "options": {"mask": "yx"}, "inputs": {"x": "a.out"}},
         {"id": "c", "type": "swizzle", "options": {"mask": "xy"}, "inputs": {"x": "b.out"}},
         {"id": "m", "type": "mul", "inputs": {"a": "c.out", "b": 4}},
         {"id": "n", "type": "mul", "inputs": {"a": "m.out", "b": 4}},
         {"id": "s", "type": "split", "inputs": {"v": "n.out"}})",
      R"("fragment": {"alpha": "s.x"})"));
  const Op *a = findOp(p, "a"), *b = findOp(p, "b"), *c = findOp(p, "c"), *m = findOp(p, "m"), *n = findOp(p, "n");
  ASSERT_TRUE(a && b && c && m && n);
  EXPECT_EQ(a->sharedOptions, b->sharedOptions);
  EXPECT_EQ(a->parsedOptions, b->parsedOptions);
  EXPECT_NE(a->sharedOptions, c->sharedOptions);
  EXPECT_EQ(c->options().at("mask"), "xy");
  ASSERT_EQ(m->inputs[1].kind, ValueRef::Kind::Const);
  EXPECT_EQ(m->inputs[1].constant_value, n->inputs[1].constant_value);
  EXPECT_EQ(n->inputs[1].constant()[0], 4.0);
}

TEST(SharedValues, NegativeZeroIsNotZero) {
  ConstantTable table;
  auto zero = table.intern(Value::scalar(0.0));
  auto negativeZero = table.intern(Value::scalar(-0.0));
  EXPECT_NE(zero, negativeZero);
  EXPECT_TRUE(std::signbit((*negativeZero)[0]));
  EXPECT_EQ(zero, table.intern(Value::scalar(0.0)));
  EXPECT_NE(zero, table.intern(Value::vector({0.0, 0.0})));  // same bits, another type
}

}  // namespace
}  // namespace wg
