#include "codegen/query_body.h"

#include "codegen/c_names.h"
#include "codegen/query_header.h"
#include "codegen/query_program.h"
#include "core/interface_tables.h"

namespace wg {

std::optional<QueryBody> queryBody(const Program& program, HeaderLanguage language, const std::string& prefix,
                                   Diagnostics& diags) {
  auto query = extractQuery(program, diags);
  if (!query) return std::nullopt;
  QueryBody body;
  body.ocean = query->ocean;
  const bool c = language == HeaderLanguage::C;
  // The struct holds the parameters a host may change; a static one was folded into the
  // program as a constant, so it is no member.
  std::vector<int> memberOf(program.parameters.size(), -1);
  for (size_t i = 0; i < program.parameters.size(); ++i) {
    if (program.parameters[i].isStatic) continue;
    memberOf[i] = static_cast<int>(body.parameters.size());
    body.parameters.push_back(program.parameters[i]);
    body.members.push_back(cIdentifier(program.parameters[i].name));
  }
  QueryWriter w(language);
  w.ocean = {prefix, query->ocean};
  std::vector<std::optional<QueryValue>> parameterValues(program.parameters.size());
  auto parameter = [&](int index) -> const QueryValue& {
    auto& v = parameterValues.at(static_cast<size_t>(index));
    if (v) return *v;
    const ProgramParameter& p = program.parameters[static_cast<size_t>(index)];
    v.emplace();
    int n = componentCount(p.type);
    for (int k = 0; k < n; ++k) {
      std::string local = "p" + std::to_string(index) + "_" + std::to_string(k);
      if (memberOf[static_cast<size_t>(index)] < 0) {  // static: its value
        v->push_back({w.bind(local, "(" + numberLiteral(p.defaultValue[k], language) + ")")});
        continue;
      }
      std::string member = body.members[static_cast<size_t>(memberOf[static_cast<size_t>(index)])];
      std::string access = (c ? "p->" : "p.") + member + (n == 1 ? "" : "[" + std::to_string(k) + "]");
      v->push_back({w.bind(local, clampedParameter(p, access, language))});
      body.readsParameters = true;
    }
    return *v;
  };
  auto builtin = [&](Builtin b) -> QueryValue {
    switch (b) {
      case Builtin::WorldPosition: return {{"x0", {"1.0", "0.0", "0.0"}}, {"0.0"}, {"z0", {"0.0", "1.0", "0.0"}}};
      case Builtin::Time: return {{"t", {"0.0", "0.0", "1.0"}}};
      case Builtin::Normal: return {{"0.0"}, {"1.0"}, {"0.0"}};
      case Builtin::CameraPosition:  // only an ocean reader's fade reads it (extractQuery)
        if (c) return {{"o->camera[0]"}, {"o->camera[1]"}, {"o->camera[2]"}};
        return {{"o.camera[0]"}, {"o.camera[1]"}, {"o.camera[2]"}};
      default: break;
    }
    throw std::logic_error("queryBody: builtin '" + std::string(builtinName(b)) + "' passed extractQuery");
  };
  std::vector<std::vector<QueryValue>> outputs(query->program.ops.size());
  auto valueOf = [&](const ValueRef& r) -> QueryValue {
    switch (r.kind) {
      case ValueRef::Kind::Op: return outputs.at(static_cast<size_t>(r.index)).at(static_cast<size_t>(r.port));
      case ValueRef::Kind::Param: return parameter(r.index);
      case ValueRef::Kind::Builtin: return builtin(static_cast<Builtin>(r.index));
      case ValueRef::Kind::Const: {
        QueryValue v;
        for (int k = 0; k < r.constant().size(); ++k) {
          std::string l = numberLiteral(r.constant()[k], language);
          v.push_back({l[0] == '-' || !std::isdigit(static_cast<unsigned char>(l[0])) ? "(" + l + ")" : l});
        }
        return v;
      }
      case ValueRef::Kind::None: return {};
    }
    return {};
  };
  bool ok = true;
  for (size_t k = 0; k < query->program.ops.size(); ++k) {
    const Op& op = query->program.ops[k];
    std::vector<QueryValue> in;
    for (const ValueRef& r : op.inputs) in.push_back(valueOf(r));
    try {
      outputs[k] = queryOp(op, in, w, std::to_string(k));
    } catch (const QueryRefusal& e) {
      withInstanceNotes(diags.error(DiagCode::NotQueryable, op.where,
                                    "node '" + op.nodeId + "' (" + op.spec->type +
                                        ") feeds the vertex displacement, but a surface query cannot evaluate it: " + e.what(),
                                    op.nodeId),
                        op);
      ok = false;
      outputs[k].assign(op.outputTypes.size(), QueryValue(4, QueryScalar{"0.0"}));
    }
  }
  if (!ok) return std::nullopt;
  QueryValue position = valueOf(query->position);
  std::vector<std::string> roots;
  for (size_t i = 0; i < 3; ++i) {
    body.position[i] = position.at(i);
    roots.push_back(body.position[i].value);
    roots.insert(roots.end(), body.position[i].d.begin(), body.position[i].d.end());
  }
  body.statements = w.text(roots);
  // A parameter the kept statements do not read is no reason to touch the struct.
  body.readsParameters = body.statements.find(c ? "p->" : "p.") != std::string::npos;
  return body;
}

std::string queryRestartTable(HeaderLanguage language) {
  // Four axes at the full reach, then the four directions between them at half of it.
  static const char* kTriples =
      "1.0, 0.0, 1.0, 0.0, 1.0, 1.0, -1.0, 0.0, 1.0, 0.0, -1.0, 1.0, "
      "0.6, 0.8, 0.5, -0.8, 0.6, 0.5, -0.6, -0.8, 0.5, 0.8, -0.6, 0.5";
  return language == HeaderLanguage::C ? std::string("const double restart[24] = {") + kTriples + "};"
                                       : std::string("const restart = [") + kTriples + "];";
}

}  // namespace wg
