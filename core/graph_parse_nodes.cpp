// Parsing a graph file: each element of "nodes", checked as soon as it ends (its id, type,
// options, inputs and editor position), and the "outputs" slots.
#include <algorithm>
#include <array>
#include <string>

#include "core/graph_parser.h"
#include "core/interface_tables.h"
#include "core/load_limits.h"

namespace wg::parsing {

// One element of "nodes", as soon as it ends; its diagnostics wait in nodeDiags_ for
// their turn (after the presets), its Node in nodes_.
void GraphParser::node(DraftValue& nv) {
  if (nodeCount() > kMaxNodes) return;  // reported alone in load()
  Diagnostics& out = nodeDiags_;
  if (nv.type != json::value_t::object) {
    out.error(DiagCode::WrongJsonType, ref(nv.at), "each node must be an object, found " + jsonTypeName(nv.type));
    return;
  }
  // Built in its place in the graph's array (reserved for the file's nodes): a Node moved
  // in afterwards moved every input's strings once more.
  Node& n = nodes_.emplace_back();
  n.where = ref(nv.at);
  std::string label;  // for diagnostics: the id when it is a valid one
  if (!nv.member("id")) {
    missing(nv, "node is missing \"id\"", {}, &out);
  } else if (auto* v = field(nv, "id", json::value_t::string, "a node's 'id'", {}, &out)) {
    n.id = std::move(v->value.get_ref<std::string&>());
    n.idWhere = ref(v->at);
    if (isIdentifier(n.id))
      label = n.id;
    else
      out.error(DiagCode::InvalidIdentifier, n.idWhere, "node id '" + n.id + "' is not an identifier " + kIdentifierRule);
  }
  checkKeys(nv, "node", {"id", "type", "options", "inputs", "editor"}, label, &out);
  if (!nv.member("type")) {
    missing(nv, "node is missing \"type\"", label, &out);
  } else if (auto* v = field(nv, "type", json::value_t::string, "a node's 'type'", label, &out)) {
    n.type = std::move(v->value.get_ref<std::string&>());
    n.typeWhere = ref(v->at);
  }
  if (auto* v = field(nv, "options", json::value_t::object, "a node's 'options'", label, &out)) {
    n.options.reserve(v->members.size());
    for (DraftValue& o : v->members)
      n.options.push_back(NodeOption{std::move(o.name), std::move(o.value), ref(o.at), ref(o.key)});
  }
  if (auto* v = field(nv, "inputs", json::value_t::object, "a node's 'inputs'", label, &out)) {
    n.inputs.reserve(v->members.size());
    for (DraftValue& e : v->members) {
      NodeInput& in = n.inputs.emplace_back();
      in.port = std::move(e.name);
      in.keyWhere = ref(e.key);
      if (!parseSource(e.value, ref(e.at), in.source, label, [&] { return "input '" + in.port + "'"; }, out))
        n.inputs.pop_back();
    }
  }
  if (auto* v = field(nv, "editor", json::value_t::object, "a node's 'editor'", label, &out)) {
    checkKeys(*v, "a node's editor position", {"x", "y"}, label, &out);
    std::array<double, 2> pos{0, 0};
    bool ok = true;
    const char* axes[2] = {"x", "y"};
    for (int a = 0; a < 2; ++a) {
      if (!v->member(axes[a])) {
        missing(*v, std::string("editor position is missing \"") + axes[a] + "\"", label, &out);
        ok = false;
      } else if (auto* c = field(*v, axes[a], json::value_t::number_float, std::string("'editor.") + axes[a] + "'",
                                 label, &out)) {
        pos[a] = c->value.get<double>();
      } else {
        ok = false;
      }
    }
    if (ok) n.editorPosition = pos;
  }
}

// A graph with nothing connected loads (the editor saves one when the user disconnects
// every output, and it must open again); resolve refuses to compile it (WG031).
void GraphParser::loadOutputs(const DraftValue& outputs, Graph& g) {
  const std::string expected(outputSlotList());
  g.outputsWhere = ref(outputs.at);
  for (const DraftValue& sv : outputs.members) {
    const std::string& stage = sv.name;
    bool knownStage = false;
    for (const auto& s : outputSlotTable()) knownStage |= stage == s.stageName;
    if (!knownStage) {
      diags_.error(DiagCode::UnknownOutputSlot, ref(sv.key), "unknown output stage '" + stage + "' " + expected);
      continue;
    }
    if (sv.type != json::value_t::object) {
      diags_.error(DiagCode::WrongJsonType, ref(sv.at),
                   "'outputs." + stage + "' must be an object, found " + jsonTypeName(sv.type));
      continue;
    }
    for (const DraftValue& slot : sv.members) {
      const std::string& name = slot.name;
      const OutputSlotRow* found = nullptr;
      for (const auto& s : outputSlotTable())
        if (stage == s.stageName && name == s.portName) found = &s;
      if (!found) {
        diags_.error(DiagCode::UnknownOutputSlot, ref(slot.key),
                     "unknown output slot '" + stage + "." + name + "' " + expected);
        continue;
      }
      GraphOutput out;
      out.slot = found->id;
      out.keyWhere = ref(slot.key);
      if (parseSource(slot.value, ref(slot.at), out.source, {}, [&] { return "output '" + stage + "." + name + "'"; },
                      diags_))
        g.outputs.push_back(std::move(out));
    }
  }
  std::stable_sort(g.outputs.begin(), g.outputs.end(),
                   [](const GraphOutput& a, const GraphOutput& b) { return a.slot < b.slot; });
}

}  // namespace wg::parsing
