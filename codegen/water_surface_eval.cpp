// The vertex stage in double (codegen/water_surface_eval.h).
#include "codegen/water_surface_eval.h"

#include <set>

#include "codegen/cpu_backend.h"
#include "nodes/texture_source.h"

namespace wg {

WaterSurfacePoint waterSurfaceAt(const Program& program, const std::vector<Value>& parameters, double x0, double z0,
                                 double t, TextureCache* textures) {
  TextureCache own;
  if (!textures) textures = &own;
  // Only what the vertex outputs read: the fragment stage's ops may sample textures the
  // vertex stage has no coordinates for.
  std::set<int> needed;
  std::vector<int> stack;
  for (const auto& o : program.outputs)
    if ((o.slot == OutputSlot::VertexPosition || o.slot == OutputSlot::VertexNormal) && o.value.kind == ValueRef::Kind::Op)
      stack.push_back(o.value.index);
  while (!stack.empty()) {
    const int k = stack.back();
    stack.pop_back();
    if (!needed.insert(k).second) continue;
    for (const auto& r : program.ops[static_cast<size_t>(k)].inputs)
      if (r.kind == ValueRef::Kind::Op) stack.push_back(r.index);
  }
  EvalEnvironment env;
  env.worldPosition = Value::vector({x0, 0, z0});
  env.normal = Value::vector({0, 1, 0});
  env.time = Value::scalar(t);
  std::vector<std::vector<Value>> outs(program.ops.size());
  auto valueOf = [&](const ValueRef& r) -> Value {
    switch (r.kind) {
      case ValueRef::Kind::Op: return outs[static_cast<size_t>(r.index)][static_cast<size_t>(r.port)];
      case ValueRef::Kind::Param: return parameters.at(static_cast<size_t>(r.index));
      case ValueRef::Kind::Const: return r.constant();
      case ValueRef::Kind::Builtin: return env.builtin(static_cast<Builtin>(r.index));
      case ValueRef::Kind::None: break;
    }
    return {};
  };
  for (int k : needed) {  // ascending: the ops are in topological order
    std::vector<Value> in;
    for (const auto& r : program.ops[static_cast<size_t>(k)].inputs) in.push_back(valueOf(r));
    outs[static_cast<size_t>(k)] = evaluateOp(program.ops[static_cast<size_t>(k)], in, env, textures, program.directory);
  }
  WaterSurfacePoint p{{x0, 0, z0}, {0, 1, 0}};
  for (const auto& o : program.outputs) {
    if (o.slot != OutputSlot::VertexPosition && o.slot != OutputSlot::VertexNormal) continue;
    const Value value = valueOf(o.value).convertedTo(Type::Vec3);
    double* to = o.slot == OutputSlot::VertexPosition ? p.position : p.normal;
    for (int i = 0; i < 3; ++i) to[i] = value[i];
  }
  return p;
}

}  // namespace wg
