// stages: what the vertex outputs reach runs in the vertex stage; what the fragment
// outputs reach runs in the fragment stage. A value computed per vertex that the fragment
// stage needs becomes a varying, except sources and uniform-only values, which the
// fragment stage recomputes (an attribute read, or the same value for every vertex).
#include "codegen/frequency.h"
#include "codegen/passes.h"

namespace wg {
namespace {

bool isFragmentOnlyBuiltin(Builtin b) { return b == Builtin::ScreenUv || b == Builtin::FragDepth; }

}  // namespace

PassResult stagePass(Program& program, PassContext& ctx) {
  size_t n = program.ops.size();
  // perVertex: the value differs between vertices (reads an attribute-derived builtin).
  std::vector<bool> perVertex(n, false);
  for (size_t i = 0; i < n; ++i) {
    const Op& op = program.ops[i];
    bool v = op.spec->isSource && !op.spec->isUniformSource;
    for (const auto& in : op.inputs) {
      if (in.kind == ValueRef::Kind::Op) v = v || perVertex[static_cast<size_t>(in.index)];
      if (in.kind == ValueRef::Kind::Builtin) v = v || !isPerDrawBuiltin(static_cast<Builtin>(in.index));
    }
    perVertex[i] = v;
  }

  std::vector<bool> inVertex(n, false);
  std::vector<std::string> vertexSlot(n);
  for (const auto& out : program.outputs)
    if (outputSlotRow(out.slot).stage == kVertexStage && out.value.kind == ValueRef::Kind::Op) {
      inVertex[static_cast<size_t>(out.value.index)] = true;
      vertexSlot[static_cast<size_t>(out.value.index)] = std::string(outputSlotName(out.slot));
    }
  for (size_t i = n; i-- > 0;) {
    if (!inVertex[i]) continue;
    for (const auto& in : program.ops[i].inputs)
      if (in.kind == ValueRef::Kind::Op && !inVertex[static_cast<size_t>(in.index)]) {
        inVertex[static_cast<size_t>(in.index)] = true;
        vertexSlot[static_cast<size_t>(in.index)] = vertexSlot[i];
      }
  }
  bool failed = false;
  for (size_t i = 0; i < n; ++i) {
    if (!inVertex[i]) continue;
    const Op& op = program.ops[i];
    bool fragmentOnly = !(op.spec->stages & kVertexStage);
    for (const auto& in : op.inputs)
      fragmentOnly |= in.kind == ValueRef::Kind::Builtin && isFragmentOnlyBuiltin(static_cast<Builtin>(in.index));
    if (fragmentOnly) {
      withInstanceNotes(ctx.diags.error(DiagCode::StageMismatch, op.where,
                                        "'" + op.spec->type + "' runs only in the fragment stage, but it feeds the vertex output '" +
                                            vertexSlot[i] + "'",
                                        op.nodeId),
                        op);
      failed = true;
    }
  }
  if (failed) return PassResult::Failed;

  // Fragment: walk back from the fragment outputs; stop at per-vertex values computed in
  // the vertex stage (they arrive as varyings).
  std::vector<bool> inFragment(n, false);
  std::vector<bool> isVarying(n, false);
  std::vector<std::vector<bool>> varyingPorts(n);
  // Deferred water (a node reads the "underwater" resource): the fragment shader runs as a
  // full-screen pass with no varyings, so it recomputes what it needs at the G-buffer's
  // surface point.
  const bool deferred = program.reads(SceneResource::Underwater);
  auto need = [&](const ValueRef& r) {
    if (r.kind != ValueRef::Kind::Op) return;
    size_t i = static_cast<size_t>(r.index);
    if (!deferred && inVertex[i] && perVertex[i] && !program.ops[i].spec->recomputeInFragment) {
      if (varyingPorts[i].empty()) varyingPorts[i].assign(program.ops[i].outputTypes.size(), false);
      varyingPorts[i][static_cast<size_t>(r.port)] = true;
      isVarying[i] = true;
      return;
    }
    inFragment[i] = true;
  };
  for (const auto& out : program.outputs)
    if (outputSlotRow(out.slot).stage == kFragmentStage) need(out.value);
  for (size_t i = n; i-- > 0;)
    if (inFragment[i])
      for (const auto& in : program.ops[i].inputs) need(in);

  program.varyings.clear();
  for (size_t i = 0; i < n; ++i) {
    Op& op = program.ops[i];
    op.stage = (inVertex[i] ? kVertexStage : 0u) | (inFragment[i] ? kFragmentStage : 0u);
    if (inFragment[i] && !(op.spec->stages & kFragmentStage)) {
      withInstanceNotes(ctx.diags.error(DiagCode::StageMismatch, op.where,
                                        "'" + op.spec->type + "' runs only in the vertex stage, but the fragment stage needs it",
                                        op.nodeId),
                        op);
      failed = true;
    }
    for (size_t p = 0; p < varyingPorts[i].size(); ++p)
      if (varyingPorts[i][p]) program.varyings.push_back(ValueRef::op(static_cast<int>(i), static_cast<int>(p)));
  }
  return failed ? PassResult::Failed : PassResult::Changed;
}

}  // namespace wg
