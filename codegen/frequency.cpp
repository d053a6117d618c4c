#include "codegen/frequency.h"

#include <algorithm>
#include <stdexcept>

namespace wg {

std::string_view frequencyName(Frequency f) {
  switch (f) {
    case Frequency::Constant: return "constant";
    case Frequency::PerDraw: return "per-draw";
    case Frequency::PerVertex: return "per-vertex";
    case Frequency::PerFragment: return "per-fragment";
  }
  throw std::logic_error("frequencyName: unknown frequency");
}

bool isPerDrawBuiltin(Builtin b) {
  switch (b) {
    case Builtin::Time:
    case Builtin::CameraPosition:
    case Builtin::CameraNearFar:
    case Builtin::View:
    case Builtin::Projection:
    case Builtin::SunDirection:
    case Builtin::PixelAngle: return true;
    case Builtin::Uv:
    case Builtin::WorldPosition:
    case Builtin::Normal:
    case Builtin::ViewDirection:
    case Builtin::ScreenUv:
    case Builtin::FragDepth: return false;
  }
  throw std::logic_error("isPerDrawBuiltin: unknown builtin");
}

Frequency frequencyOf(const ValueRef& ref, const std::vector<Frequency>& ops) {
  switch (ref.kind) {
    case ValueRef::Kind::None:
    case ValueRef::Kind::Const: return Frequency::Constant;
    case ValueRef::Kind::Param: return Frequency::PerDraw;
    case ValueRef::Kind::Builtin: {
      Builtin b = static_cast<Builtin>(ref.index);
      if (isPerDrawBuiltin(b)) return Frequency::PerDraw;
      return b == Builtin::ScreenUv || b == Builtin::FragDepth ? Frequency::PerFragment : Frequency::PerVertex;
    }
    case ValueRef::Kind::Op: return ops.at(static_cast<size_t>(ref.index));
  }
  throw std::logic_error("frequencyOf: unknown value kind");
}

std::vector<Frequency> analyseFrequency(const Program& program) {
  std::vector<Frequency> out(program.ops.size(), Frequency::Constant);
  // First whether each op varies over the surface at all (ops are topological, so one
  // forward walk sees every input first); the stage then says at which rate.
  std::vector<bool> varies(program.ops.size(), false);
  for (size_t i = 0; i < program.ops.size(); ++i) {
    const Op& op = program.ops[i];
    Frequency f = Frequency::Constant;
    bool v = false;
    if (op.spec->isSource || op.spec->ownGlsl) {  // a function node: its GLSL, never a CPU copy, computes it
      if (op.spec->isUniformSource) f = Frequency::PerDraw;
      else v = true;
    }
    for (const auto& in : op.inputs) {
      if (in.kind == ValueRef::Kind::Op) {
        size_t j = static_cast<size_t>(in.index);
        v = v || varies[j];
        f = std::max(f, out[j]);
      } else {
        Frequency g = frequencyOf(in, out);
        v = v || g > Frequency::PerDraw;
        f = std::max(f, std::min(g, Frequency::PerDraw));
      }
    }
    varies[i] = v;
    // Only the vertex stage computes it: a varying carries it to the fragment stage.
    if (v) f = op.stage == kVertexStage ? Frequency::PerVertex : Frequency::PerFragment;
    out[i] = f;
  }
  return out;
}

}  // namespace wg
