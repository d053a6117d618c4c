#include "core/port_typing.h"

#include <stdexcept>

namespace wg {

PortTyping typePorts(const NodeSpec& spec, const ParsedOptions& options, const std::vector<Type>& sourceTypes,
                     const std::function<std::string(int)>& describe) {
  PortTyping r;
  size_t nin = spec.inputs.size();
  auto fail = [&](size_t input, std::string message) {
    r.error = std::move(message);
    r.errorInput = static_cast<int>(input);
    return r;
  };
  // Gen ports: one float-or-vector type for the node; floats splat to it.
  Type gen = Type::Float;
  int genFrom = -1;
  for (size_t i = 0; i < nin; ++i) {
    if (spec.inputs[i].kind != PortKind::Gen) continue;
    Type t = sourceTypes[i];
    if (!isFloatScalarOrVector(t))
      return fail(i, "input '" + spec.inputs[i].name + "' takes float, vec2, vec3 or vec4, but " +
                         describe(static_cast<int>(i)) + " is " + std::string(typeName(t)));
    if (t == Type::Float) continue;
    if (gen == Type::Float) {
      gen = t;
      genFrom = static_cast<int>(i);
    } else if (t != gen) {
      return fail(i, "input '" + spec.inputs[i].name + "' is " + std::string(typeName(t)) + " but input '" +
                         spec.inputs[static_cast<size_t>(genFrom)].name + "' is " + std::string(typeName(gen)) +
                         "; only a float splats to a vector");
    }
  }
  for (size_t i = 0; i < nin; ++i) {
    const PortSpec& p = spec.inputs[i];
    r.inputTypes.push_back(p.kind == PortKind::Fixed ? p.type : p.kind == PortKind::Gen ? gen : sourceTypes[i]);
  }
  for (const auto& p : spec.outputs)
    r.outputTypes.push_back(p.kind == PortKind::Fixed ? p.type : p.kind == PortKind::Gen ? gen : Type::Invalid);
  if (spec.infer) {
    InferContext ctx{spec, options, std::move(r.inputTypes), std::move(r.outputTypes), {}, -1};
    spec.infer(ctx);
    if (!ctx.error.empty()) {
      r.error = ctx.error;
      r.errorInput = ctx.errorInput;
      return r;
    }
    r.inputTypes = std::move(ctx.inputTypes);
    r.outputTypes = std::move(ctx.outputTypes);
  }
  for (size_t i = 0; i < nin; ++i)
    if (!implicitlyConvertible(sourceTypes[i], r.inputTypes[i]))
      return fail(i, "input '" + spec.inputs[i].name + "' expects " + std::string(typeName(r.inputTypes[i])) +
                         ", but " + describe(static_cast<int>(i)) + " is " + std::string(typeName(sourceTypes[i])));
  // infer may leave an output Invalid: it does not exist for these inputs (split.w of a
  // vec3); referring to it is reported where the reference is.
  if (!spec.infer)
    for (size_t i = 0; i < r.outputTypes.size(); ++i)
      if (r.outputTypes[i] == Type::Invalid)
        throw std::logic_error("node spec '" + spec.type + "' left output '" + spec.outputs[i].name + "' untyped");
  return r;
}

}  // namespace wg
