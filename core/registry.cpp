#include "core/registry.h"

#include <set>
#include <stdexcept>

#include "core/node_options.h"
#include "core/texture_check.h"

namespace wg {

// The node's parse function reads its defaults without a mistake (OptionReader checks
// each name, kind and choice) and reads every option but textures, which emit and eval
// fetch by name (EmitContext::texture, EvalContext::sampleTexture).
static void checkOptionsParse(const NodeSpec& s) {
  auto fail = [&](const std::string& why) { throw std::logic_error("node spec '" + s.type + "': " + why); };
  bool readsAny = false;
  for (const auto& o : s.options) readsAny |= o.kind != OptionSpec::Kind::Texture;
  if (!s.parseOptions) {
    if (readsAny) fail("options without a parseOptions function");
    return;
  }
  nlohmann::json defaults = completeOptions(s, nlohmann::json::object());
  OptionReader reader(s, defaults);
  if (!s.parseOptions(reader)) fail("parseOptions returned nothing");
  for (const auto& o : s.options)
    if (o.kind != OptionSpec::Kind::Texture && !reader.namesRead().count(o.name))
      fail("parseOptions does not read option '" + o.name + "'");
}

// A hard case names only ports and options the node has, with valid option values: a
// misspelt name would leave the default in place and test that instead.
static void checkHardCaseNames(const NodeSpec& s, const HardCase& hc) {
  auto fail = [&](const std::string& why) {
    throw std::logic_error("node spec '" + s.type + "', hard case '" + hc.name + "': " + why);
  };
  if (!hc.options.is_object() && !hc.options.is_null()) fail("options are not an object");  // `{}` is null
  for (auto it = hc.options.begin(); it != hc.options.end(); ++it) {
    int oi = s.optionIndex(it.key());
    if (oi < 0) fail("no option '" + it.key() + "'");
    const OptionSpec& o = s.options[static_cast<size_t>(oi)];
    if (o.kind == OptionSpec::Kind::Texture) continue;  // a path is relative to a graph; there is none here
    std::string why = checkOption(o, it.value(), "");
    if (!why.empty()) fail("option '" + it.key() + "' " + why);
  }
  NodePorts ports = portsOfNode(s, hc.options);  // an expression's inputs follow from its options
  for (const auto& [port, value] : hc.inputs)
    if (ports.inputIndex(port) < 0) fail("no input '" + port + "'");
  if (!hc.output.empty() && ports.outputIndex(hc.output) < 0) fail("no output '" + hc.output + "'");
  if (s.parseOptions) s.parseOptions(OptionReader(s, completeOptions(s, hc.options)));
}

// A node that expands into ops (NodeSpec::expand) has no emit or eval of its own, and the
// ports its options give are Fixed: resolve converts each input to its port's type before
// the expansion sees it.
static void checkExpansion(const NodeSpec& s) {
  auto fail = [&](const std::string& why) { throw std::logic_error("node spec '" + s.type + "': " + why); };
  if (s.emit || s.eval) fail("expands into ops and also has emit or eval");
  if (!s.portsFor) return;
  NodePorts ports = s.portsFor(*parseOptions(s, completeOptions(s, nlohmann::json::object())));
  for (const auto& p : ports.inputs)
    if (p.kind != PortKind::Fixed) fail("input '" + p.name + "' of an expanding node is not Fixed");
}

// A malformed spec is a programming error in nodes/, caught by the first test that
// builds the registry, never a user-facing condition.
static void checkSpec(const NodeSpec& s) {
  auto fail = [&](const std::string& why) {
    throw std::logic_error("node spec '" + s.type + "': " + why);
  };
  if (s.type.empty()) fail("empty type name");
  if (s.portsFor && !s.expand) fail("ports that follow from the options, but no expand function");
  if (s.expand) {
    checkExpansion(s);
  } else {
    if (!s.emit) fail("no emit function");
    if (!s.eval) fail("no eval function (every node has a double reference)");
  }
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
  if (custom && !s.infer && !s.expand) fail("custom-typed ports need an infer function");
  // A texture option's default is a builtin texture: a path would be relative to no graph
  // (and resolve shares one completed default per type between graph files).
  for (const auto& o : s.options)
    if (o.kind == OptionSpec::Kind::Texture &&
        !(o.defaultValue.is_string() && o.defaultValue.get_ref<const std::string&>().rfind(kBuiltinTexturePrefix, 0) == 0))
      fail("texture option '" + o.name + "' must default to a builtin texture");
  checkOptionsParse(s);
  for (const auto& hc : s.hardCases) checkHardCaseNames(s, hc);
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
