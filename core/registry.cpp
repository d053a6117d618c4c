#include "core/registry.h"

#include <set>
#include <stdexcept>

namespace wg {

// A malformed spec is a programming error in nodes/, caught by the first test that
// builds the registry, never a user-facing condition.
static void checkSpec(const NodeSpec& s) {
  auto fail = [&](const std::string& why) {
    throw std::logic_error("node spec '" + s.type + "': " + why);
  };
  if (s.type.empty()) fail("empty type name");
  if (!s.emit) fail("no emit function");
  if (!s.eval) fail("no eval function (every node has a double reference)");
  if (s.outputs.empty()) fail("no outputs");
  if (s.summary.empty()) fail("no summary");
  std::set<std::string> names;
  for (const auto& p : s.inputs)
    if (!names.insert("in:" + p.name).second) fail("duplicate input " + p.name);
  for (const auto& p : s.outputs)
    if (!names.insert("out:" + p.name).second) fail("duplicate output " + p.name);
  for (const auto& o : s.options)
    if (!names.insert("opt:" + o.name).second) fail("duplicate option " + o.name);
  bool custom = false;
  for (const auto& p : s.inputs) custom |= p.kind == PortKind::Custom;
  for (const auto& p : s.outputs) custom |= p.kind == PortKind::Custom;
  if (custom && !s.infer) fail("custom-typed ports need an infer function");
}

void Registry::add(NodeSpec spec) {
  checkSpec(spec);
  std::string key = spec.type;
  if (specs_.count(key)) throw std::logic_error("node type registered twice: " + key);
  specs_.emplace(key, std::make_unique<NodeSpec>(std::move(spec)));
}

const NodeSpec* Registry::find(std::string_view type) const {
  auto it = specs_.find(type);
  return it == specs_.end() ? nullptr : it->second.get();
}

std::vector<const NodeSpec*> Registry::all() const {
  std::vector<const NodeSpec*> out;
  out.reserve(specs_.size());
  for (const auto& [name, spec] : specs_) out.push_back(spec.get());
  return out;
}

}  // namespace wg
