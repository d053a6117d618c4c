#include "core/program.h"

namespace wg {

const ProgramOutput* Program::output(OutputSlot slot) const {
  for (const auto& o : outputs)
    if (o.slot == slot) return &o;
  return nullptr;
}

Type Program::typeOf(const ValueRef& v) const {
  switch (v.kind) {
    case ValueRef::Kind::Op: return ops[static_cast<size_t>(v.index)].outputTypes[static_cast<size_t>(v.port)];
    case ValueRef::Kind::Param: return parameters[static_cast<size_t>(v.index)].type;
    case ValueRef::Kind::Const: return v.constant.type;
    case ValueRef::Kind::Builtin: return builtinType(static_cast<Builtin>(v.index));
    case ValueRef::Kind::None: return Type::Invalid;
  }
  return Type::Invalid;
}

}  // namespace wg
