#include "codegen/query_program.h"

#include <map>

#include "codegen/query_ops.h"
#include "core/interface_tables.h"

namespace wg {

namespace {

// The inputs an op's output port reads: vertex_output's position reads its position and
// displacement, not the normal it hands on beside them; every other op reads them all.
std::vector<size_t> inputsRead(const Op& op, int port) {
  std::vector<size_t> all;
  if (op.spec->type == "vertex_output" && port == 0) return {0, 1};
  for (size_t i = 0; i < op.inputs.size(); ++i) all.push_back(i);
  return all;
}

// What a builtin is in a query, or "" when it is one a query has: the undisplaced point,
// the time, the flat mesh's normal.
std::string builtinRefusal(Builtin b) {
  switch (b) {
    case Builtin::WorldPosition:
    case Builtin::Time:
    case Builtin::Normal: return "";
    default: break;
  }
  return "it reads the builtin '" + std::string(builtinName(b)) +
         "', which a surface query does not have (it knows the point x0, z0, the time and the parameters)";
}

// Node types that draw a surface other than the mesh's: trochoid_wave finds a height field
// along each pixel's view ray on a flat mesh. The vertex stage does not move the water
// there, so a query of it would answer the flat plane while the picture shows waves.
bool drawsItsOwnSurface(const Op& op) { return op.spec->type == "trochoid_wave"; }

}  // namespace

std::optional<QueryProgram> extractQuery(const Program& program, Diagnostics& diags) {
  QueryProgram q;
  q.program.graphName = program.graphName;
  q.program.file = program.file;
  q.program.directory = program.directory;
  q.program.parameters = program.parameters;
  bool ok = true;
  for (const Op& op : program.ops)
    if (drawsItsOwnSurface(op)) {
      withInstanceNotes(diags.error(DiagCode::NotQueryable, op.where,
                                    "node '" + op.nodeId + "' (" + op.spec->type +
                                        ") draws a surface the fragment stage finds along each view ray, which the "
                                        "vertex stage does not displace; a surface query would answer the flat mesh",
                                    op.nodeId),
                        op);
      ok = false;
    }
  if (!ok) return std::nullopt;
  const ProgramOutput* out = program.output(OutputSlot::VertexPosition);
  if (!out || out->value.kind != ValueRef::Kind::Op) {  // the water is not displaced
    q.position = ValueRef::builtin(Builtin::WorldPosition);
    if (out && out->value.kind == ValueRef::Kind::Builtin &&
        static_cast<Builtin>(out->value.index) == Builtin::WorldPosition)
      return q;
    if (out && out->value.kind != ValueRef::Kind::Builtin) {  // a constant or a parameter: not the point
      diags.error(DiagCode::NotQueryable, out->where,
                  "the vertex position is not computed from the water point; a surface query needs the displacement");
      return std::nullopt;
    }
    if (out) {
      diags.error(DiagCode::NotQueryable, out->where, builtinRefusal(static_cast<Builtin>(out->value.index)));
      return std::nullopt;
    }
    return q;
  }
  // Mark the cone: which ports of which ops the position reads, walking back in order.
  int oceanOp = -1;
  std::vector<std::vector<bool>> read(program.ops.size());
  for (size_t i = 0; i < program.ops.size(); ++i) read[i].assign(program.ops[i].outputTypes.size(), false);
  read[static_cast<size_t>(out->value.index)][static_cast<size_t>(out->value.port)] = true;
  for (size_t k = program.ops.size(); k-- > 0;) {
    const Op& op = program.ops[k];
    bool any = false;
    for (size_t p = 0; p < read[k].size(); ++p) any = any || read[k][p];
    if (!any) continue;
    auto refuse = [&](const std::string& why) {
      withInstanceNotes(diags.error(DiagCode::NotQueryable, op.where,
                                    "node '" + op.nodeId + "' (" + op.spec->type +
                                        ") feeds the vertex displacement, but a surface query cannot evaluate it: " + why,
                                    op.nodeId),
                        op);
      ok = false;
    };
    if (!queryOpKnown(op.spec->type)) {
      refuse("node type '" + op.spec->type + "' has no form for surface queries (--target query-c, query-js)");
      continue;
    }
    if (op.spec->type == "gerstner_waves")
      for (size_t p = 1; p < read[k].size(); ++p)
        if (read[k][p]) refuse("the displacement reads its output '" + op.spec->outputs[p].name + "', which the query does not differentiate; displace by its position");
    if (op.spec->type == "ocean_displacement" && read[k].size() > 1 && read[k][1])
      refuse("the displacement reads its output 'normal', which the query does not differentiate; displace by its position");
    if (op.spec->type == "ocean_spectrum") {
      // One state per query: a second sea would need a second one.
      if (oceanOp >= 0 && program.ops[static_cast<size_t>(oceanOp)].parsedOptions != op.parsedOptions)
        refuse("the displacement reads two ocean_spectrum nodes ('" + op.nodeId + "' and '" +
               program.ops[static_cast<size_t>(oceanOp)].nodeId + "'); a query keeps the state of one");
      oceanOp = static_cast<int>(k);
    }
    for (int p = 0; p < static_cast<int>(read[k].size()); ++p) {
      if (!read[k][static_cast<size_t>(p)]) continue;
      for (size_t i : inputsRead(op, p)) {
        const ValueRef& r = op.inputs[i];
        if (r.kind == ValueRef::Kind::Op) read[static_cast<size_t>(r.index)][static_cast<size_t>(r.port)] = true;
        if (r.kind == ValueRef::Kind::Builtin) {
          // The readers' fade distance: the ocean state holds the camera (codegen/query_ocean.h).
          if (op.spec->type == "ocean_displacement" && static_cast<Builtin>(r.index) == Builtin::CameraPosition) continue;
          std::string why = builtinRefusal(static_cast<Builtin>(r.index));
          if (!why.empty()) refuse(why);
        }
      }
    }
  }
  if (!ok) return std::nullopt;
  // Renumber the cone's ops.
  std::map<int, int> index;
  for (size_t k = 0; k < program.ops.size(); ++k) {
    bool any = false;
    for (bool b : read[k]) any = any || b;
    if (!any) continue;
    index[static_cast<int>(k)] = static_cast<int>(q.program.ops.size());
    q.program.ops.push_back(program.ops[k]);
    q.portsRead.push_back(read[k]);
  }
  for (Op& op : q.program.ops)
    for (ValueRef& r : op.inputs)
      if (r.kind == ValueRef::Kind::Op) {
        auto it = index.find(r.index);
        // An input the cone does not read (vertex_output's normal) points nowhere.
        r = it == index.end() ? ValueRef{} : ValueRef::op(it->second, r.port);
      }
  q.position = ValueRef::op(index.at(out->value.index), out->value.port);
  if (oceanOp >= 0) q.ocean = &program.ops[static_cast<size_t>(oceanOp)].parsedOptions->as<ocean::OceanSettings>();
  return q;
}

}  // namespace wg
