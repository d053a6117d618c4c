// TypeList, an op's port types held inline: lists within the inline room and past it keep
// every element through growth, copies and moves, and compare by their elements; a node
// with more ports than the inline room is typed port by port.
#include "core/type_list.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "core/node_spec.h"
#include "core/port_typing.h"

namespace wg {
namespace {

// A varied sequence, so a lost or shifted element shows.
Type typeAt(size_t i) { return static_cast<Type>(1 + i % 4); }  // Float, Vec2, Vec3, Vec4

TypeList listOf(size_t n) {
  TypeList l;
  for (size_t i = 0; i < n; ++i) l.push_back(typeAt(i));
  return l;
}

void expectSequence(const TypeList& l, size_t n) {
  ASSERT_EQ(l.size(), n);
  for (size_t i = 0; i < n; ++i) EXPECT_EQ(l[i], typeAt(i)) << i;
}

TEST(TypeList, KeepsEveryElementInlineAndPastTheInlineRoom) {
  for (size_t n : {size_t{0}, size_t{1}, TypeList::kInline - 1, TypeList::kInline, TypeList::kInline + 1, size_t{200}}) {
    SCOPED_TRACE(n);
    TypeList l = listOf(n);
    expectSequence(l, n);
    EXPECT_EQ(l.empty(), n == 0);
    EXPECT_EQ(static_cast<size_t>(l.end() - l.begin()), n);
  }
}

TEST(TypeList, CopiesAndMovesAreIndependentAndComplete) {
  for (size_t n : {size_t{3}, TypeList::kInline + 5}) {
    SCOPED_TRACE(n);
    TypeList a = listOf(n);
    TypeList copy = a;
    copy[0] = Type::Mat4;  // the original must not see it
    EXPECT_EQ(a[0], typeAt(0));
    TypeList moved = std::move(a);
    expectSequence(moved, n);
    EXPECT_TRUE(a.empty());  // NOLINT(bugprone-use-after-move): a moved-from list is empty
    a = moved;               // and usable again
    expectSequence(a, n);
    TypeList assigned;
    assigned = std::move(moved);
    expectSequence(assigned, n);
    TypeList self = listOf(n);
    self = *&self;  // self-assignment keeps it
    expectSequence(self, n);
  }
  // A short list moved over a long one and back.
  TypeList longList = listOf(TypeList::kInline * 3), shortList = listOf(2);
  longList = std::move(shortList);
  expectSequence(longList, 2);
  shortList = listOf(TypeList::kInline * 3);
  expectSequence(shortList, TypeList::kInline * 3);
}

TEST(TypeList, ComparesByElementsAndConvertsFromAVector) {
  std::vector<Type> v{Type::Float, Type::Vec3, Type::Vec3};
  TypeList fromVector = v;
  EXPECT_EQ(fromVector, (TypeList{Type::Float, Type::Vec3, Type::Vec3}));
  EXPECT_FALSE(fromVector == (TypeList{Type::Float, Type::Vec3}));
  EXPECT_FALSE(fromVector == (TypeList{Type::Float, Type::Vec3, Type::Vec4}));
  EXPECT_EQ(TypeList(4, Type::Vec2), (TypeList{Type::Vec2, Type::Vec2, Type::Vec2, Type::Vec2}));
  TypeList r = listOf(3);
  r.resize(TypeList::kInline + 2, Type::Bool);
  EXPECT_EQ(r[2], typeAt(2));
  EXPECT_EQ(r[TypeList::kInline + 1], Type::Bool);
  EXPECT_THROW((void)r.at(TypeList::kInline + 2), std::out_of_range);
}

// A node with more ports than the inline room (no registered node has one today: the widest,
// `underwater`, has 16): typePorts builds its lists on the heap, hands them through
// `infer` and back, and every port keeps its type.
TEST(TypeList, PortTypingOfANodeWiderThanTheInlineRoom) {
  const size_t n = TypeList::kInline + 4;
  NodeSpec spec;
  spec.type = "wide";
  for (size_t i = 0; i < n; ++i) {
    PortSpec port;
    port.name = "in" + std::to_string(i);
    port.kind = i % 3 == 0 ? PortKind::Fixed : PortKind::Gen;  // Fixed ports stay float, Gen ports unify
    spec.inputs.push_back(port);
  }
  PortSpec out;
  out.name = "out";
  out.kind = PortKind::Gen;
  spec.outputs.push_back(out);
  bool inferSawEveryPort = false;
  spec.infer = [&](InferContext& ctx) {
    inferSawEveryPort = ctx.inputTypes.size() == n && ctx.inputTypes[n - 1] == Type::Vec3;
    ctx.outputTypes[0] = ctx.inputTypes[n - 1];
  };
  std::vector<Type> sources(n, Type::Float);
  for (size_t i = 0; i < n; ++i)
    if (i % 3 != 0 && i % 2 == 1) sources[i] = Type::Vec3;  // some Gen ports get vec3, the rest floats that splat
  OptionsOf<int> none(0);
  PortTyping t = typePorts(spec, none, sources, [](int) { return std::string("a source"); });
  ASSERT_TRUE(t.error.empty()) << t.error;
  EXPECT_TRUE(inferSawEveryPort);
  ASSERT_EQ(t.inputTypes.size(), n);
  for (size_t i = 0; i < n; ++i) EXPECT_EQ(t.inputTypes[i], i % 3 == 0 ? Type::Float : Type::Vec3) << i;
  ASSERT_EQ(t.outputTypes.size(), 1u);
  EXPECT_EQ(t.outputTypes[0], Type::Vec3);
}

}  // namespace
}  // namespace wg
