#include "core/program.h"

namespace wg {

const ProgramOutput* Program::output(OutputSlot slot) const {
  for (const auto& o : outputs)
    if (o.slot == slot) return &o;
  return nullptr;
}

std::vector<SceneResource> Program::sceneResources() const {
  std::vector<SceneResource> out;
  for (const auto& row : sceneResourceTable())
    if (reads(row.id)) out.push_back(row.id);
  return out;
}

bool Program::reads(SceneResource r) const {
  for (const auto& op : ops)
    for (SceneResource used : op.spec->resources)
      if (used == r) return true;
  return false;
}

Type Program::typeOf(const ValueRef& v) const {
  switch (v.kind) {
    case ValueRef::Kind::Op: return ops[static_cast<size_t>(v.index)].outputTypes[static_cast<size_t>(v.port)];
    case ValueRef::Kind::Param: return parameters[static_cast<size_t>(v.index)].type;
    case ValueRef::Kind::Const: return v.constant().type;
    case ValueRef::Kind::Builtin: return builtinType(static_cast<Builtin>(v.index));
    case ValueRef::Kind::None: return Type::Invalid;
  }
  return Type::Invalid;
}

}  // namespace wg
