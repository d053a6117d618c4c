#pragma once
// The compiler's passes, each a function from one Program to the next (one file each).
// compile.cpp runs them as a recipe: bypass -> specialise -> prune -> (fold -> simplify -> cse,
// repeated until none changes anything) -> prune -> stages (runPassRecipe below).
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostic.h"
#include "core/program.h"

namespace wg {

enum class PassResult { Unchanged, Changed, Failed };

struct PassContext {
  Diagnostics& diags;
};

// Ops whose `bypass` option is on become the values their node declares for "off".
PassResult bypassPass(Program& program, PassContext& ctx);
// Static parameters become constants (never uniforms), so folding can remove them.
PassResult specialisePass(Program& program, PassContext& ctx);
// Removes ops and parameters that no output reaches; records why in program.removed.
PassResult prunePass(Program& program, PassContext& ctx);
// Evaluates ops whose inputs are all constant through their double `eval`.
PassResult foldPass(Program& program, PassContext& ctx);
// Replaces ops that reduce to one of their inputs (x * 1, x + 0, mix(a, b, 0)).
PassResult simplifyPass(Program& program, PassContext& ctx);
// Merges ops of the same type, options and inputs.
PassResult csePass(Program& program, PassContext& ctx);
// Decides the stage of every op (Op::stage bits); a fragment-only op that feeds a
// vertex output is an error.
PassResult stagePass(Program& program, PassContext& ctx);

// Called before and after each pass the recipe runs, with the pass's name ("bypass", "specialise",
// "prune", "fold", "simplify", "cse", "prune_final", "stages"): the compile benchmarks time
// each pass through these without a second copy of the recipe.
struct PassHooks {
  std::function<void(std::string_view pass)> before, after;
};

// The recipe: bypass -> specialise -> prune -> (fold -> simplify -> cse, until none changes
// anything) -> prune -> stages. False when a pass failed (its diagnostics say why).
bool runPassRecipe(Program& program, PassContext& ctx, const PassHooks* hooks = nullptr);

// Rewrites every reference through `replace` (indexed by op, then port; a None entry
// keeps the reference), then drops ops whose `keep` is false, renumbering the rest.
void rewriteProgram(Program& program, const std::vector<std::vector<ValueRef>>& replace,
                    const std::vector<bool>& keep);
// Points `op`'s inputs that read an op already replaced in `replace` (earlier in
// topological order) at its replacement: the passes that replace as they go call it first.
void forwardReplacedInputs(Op& op, const std::vector<std::vector<ValueRef>>& replace);
// For each op, whether some output reaches it.
std::vector<bool> reachableOps(const Program& program);

}  // namespace wg
