#include "accuracy/fragment_program.h"

#include <stdexcept>

namespace wg::accuracy {

FragmentProgram fragmentProgram(const Program& source) {
  const ProgramOutput* color = source.output(OutputSlot::FragmentColor);
  if (!color) throw std::invalid_argument("the program has no fragment colour");
  FragmentProgram out;
  Program& p = out.program;
  p.graphName = source.graphName;
  p.file = source.file;
  p.directory = source.directory;
  p.parameters = source.parameters;
  // A varying's value arrives as a parameter; its default is never used (set per pixel).
  std::vector<std::vector<int>> varyingParameter(source.ops.size());
  for (const ValueRef& v : source.varyings) {
    const Op& op = source.ops[static_cast<size_t>(v.index)];
    auto& ports = varyingParameter[static_cast<size_t>(v.index)];
    if (ports.empty()) ports.assign(op.outputTypes.size(), -1);
    ProgramParameter param;
    param.name = "varying " + op.nodeId + "." + op.spec->outputs[static_cast<size_t>(v.port)].name;
    param.type = op.outputTypes[static_cast<size_t>(v.port)];
    param.defaultValue = Value::ofType(param.type);
    ports[static_cast<size_t>(v.port)] = static_cast<int>(p.parameters.size());
    out.varyingParameters.push_back(static_cast<int>(p.parameters.size()));
    p.parameters.push_back(param);
  }
  std::vector<int> newIndex(source.ops.size(), -1);
  auto remap = [&](const ValueRef& r) {
    if (r.kind != ValueRef::Kind::Op) return r;
    size_t i = static_cast<size_t>(r.index);
    if (newIndex[i] >= 0) return ValueRef::op(newIndex[i], r.port);
    const auto& ports = varyingParameter[i];
    if (static_cast<size_t>(r.port) < ports.size() && ports[static_cast<size_t>(r.port)] >= 0)
      return ValueRef::param(ports[static_cast<size_t>(r.port)]);
    throw std::logic_error("fragmentProgram: op '" + source.ops[i].nodeId + "' is neither in the fragment stage nor a varying");
  };
  for (size_t i = 0; i < source.ops.size(); ++i) {
    if (!(source.ops[i].stage & kFragmentStage)) continue;
    Op op = source.ops[i];
    for (auto& in : op.inputs) in = remap(in);
    newIndex[i] = static_cast<int>(p.ops.size());
    p.ops.push_back(std::move(op));
  }
  ProgramOutput c = *color;
  c.value = remap(color->value);
  p.outputs = {c};
  return out;
}

}  // namespace wg::accuracy
