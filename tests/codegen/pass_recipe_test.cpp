// The recipe's turns of fold, simplify and cse: each exposes work for the others, so they
// take turns until none changes anything, and a pass is not run again when nothing changed
// since its own last run (each is one forward sweep: a second run on the same program
// changes nothing). The hooks count the runs.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "pass_test_support.h"

namespace wg {
namespace {

using namespace passtest;

struct Runs {
  std::map<std::string, int> count;
  std::string order;
};

Runs runRecipe(Program& p) {
  Runs runs;
  PassHooks hooks;
  hooks.before = [&](std::string_view name) {
    ++runs.count[std::string(name)];
    runs.order += (runs.order.empty() ? "" : " ") + std::string(name);
  };
  Diagnostics diags;
  PassContext ctx{diags};
  EXPECT_TRUE(runPassRecipe(p, ctx, &hooks)) << allText(diags);
  return runs;
}

int opsOfType(const Program& p, const std::string& type) {
  int n = 0;
  for (const auto& op : p.ops) n += op.spec->type == type;
  return n;
}

// fold makes k a constant 0, which makes y = p + 0 simplify to p, which makes the two
// products p * 2 and y * 2 one computation for cse: all in the first round. The second
// round finds nothing for fold and simplify, and cse, which changed the program last, does
// not run again.
TEST(Recipe, TurnsEndWhenThePassThatChangedLastComesRound) {
  Program p = resolveText(R"({"version": 1, "name": "chain",
    "parameters": {"p": {"type": "float", "default": 0.5}},
    "nodes": [
      {"id": "k", "type": "add", "inputs": {"a": 1, "b": -1}},
      {"id": "y", "type": "add", "inputs": {"a": "$p", "b": "k.out"}},
      {"id": "z1", "type": "mul", "inputs": {"a": "$p", "b": 2}},
      {"id": "z2", "type": "mul", "inputs": {"a": "y.out", "b": 2}},
      {"id": "d", "type": "sub", "inputs": {"a": "z1.out", "b": "z2.out"}},
      {"id": "c", "type": "mix", "inputs": {"a": [0, 0, 0], "b": [1, 1, 1], "t": "d.out"}}
    ],
    "outputs": {"fragment": {"color": "c.out"}}})");
  ASSERT_EQ(opsOfType(p, "mul"), 2);
  ASSERT_EQ(opsOfType(p, "add"), 2);
  Runs runs = runRecipe(p);
  EXPECT_EQ(opsOfType(p, "mul"), 1);  // merged by cse
  EXPECT_EQ(opsOfType(p, "add"), 0);  // k folded, y simplified
  EXPECT_EQ(runs.count["fold"], 2) << runs.order;
  EXPECT_EQ(runs.count["simplify"], 2) << runs.order;
  EXPECT_EQ(runs.count["cse"], 1) << runs.order;
  // Running the recipe again finds nothing: the turns stopped at the fixed point.
  Program again = p;
  Runs second = runRecipe(again);
  EXPECT_EQ(again.ops.size(), p.ops.size());
  EXPECT_EQ(second.count["fold"], 1) << second.order;
  EXPECT_EQ(second.count["cse"], 1) << second.order;
}

// Work one pass exposes for another in the next round: simplify turns mix(5, p, 0) into the
// constant 5 after fold has run, so 5 * 2 folds only in the second round. The turns go on
// until fold, which changed last, comes round again, and end at the same program as the
// full rounds the recipe ran before (every pass again until a round changes nothing).
TEST(Recipe, EarlyStopReachesTheSameProgramAsFullRounds) {
  const std::string json = R"({"version": 1, "name": "chain2",
    "parameters": {"p": {"type": "float", "default": 0.5}},
    "nodes": [
      {"id": "m", "type": "mix", "inputs": {"a": 5, "b": "$p", "t": 0}},
      {"id": "u", "type": "mul", "inputs": {"a": "m.out", "b": 2}},
      {"id": "s", "type": "add", "inputs": {"a": "u.out", "b": "$p"}},
      {"id": "c", "type": "mix", "inputs": {"a": [0, 0, 0], "b": [1, 1, 1], "t": "s.out"}}
    ],
    "outputs": {"fragment": {"color": "c.out"}}})";
  Program turns = resolveText(json);
  Runs runs = runRecipe(turns);
  EXPECT_EQ(runs.order, "bypass specialise prune fold simplify cse fold simplify cse prune_final stages");
  // The old rounds, written out: fold, simplify and cse each run until a round changes nothing.
  Program rounds = resolveText(json);
  Diagnostics diags;
  PassContext ctx{diags};
  bypassPass(rounds, ctx);
  specialisePass(rounds, ctx);
  prunePass(rounds, ctx);
  for (int round = 0; round < 8; ++round) {
    bool changed = foldPass(rounds, ctx) == PassResult::Changed;
    changed |= simplifyPass(rounds, ctx) == PassResult::Changed;
    changed |= csePass(rounds, ctx) == PassResult::Changed;
    if (!changed) break;
  }
  prunePass(rounds, ctx);
  stagePass(rounds, ctx);
  ASSERT_EQ(turns.ops.size(), rounds.ops.size());
  for (size_t i = 0; i < turns.ops.size(); ++i) EXPECT_EQ(turns.ops[i].spec->type, rounds.ops[i].spec->type) << i;
  EXPECT_EQ(opsOfType(turns, "mul"), 0);  // 5 * 2 folded in the second round
  EXPECT_EQ(opsOfType(turns, "add"), 1);
}

}  // namespace
}  // namespace wg
