#include "core/registry.h"

#include <algorithm>
#include <set>
#include <stdexcept>

#include "core/node_options.h"
#include "core/texture_check.h"

namespace wg {

// The levels of the scene-pass resolution knob (kResolutionOption), cheapest first. 0.75
// (56 % of the pixels) is there because half size fails a 45 dB budget at the first step
// on the example graphs: depth and the G-buffer are read nearest, so every edge moves.
static constexpr double kResolutionLevels[] = {0.25, 0.5, 0.75, 1.0};

// The node's parse function reads its defaults without a mistake (OptionReader checks
// each name, kind and choice) and reads every option but textures, which emit and eval
// fetch by name (EmitContext::texture, EvalContext::sampleTexture).
static void checkOptionsParse(const NodeSpec& s) {
  auto fail = [&](const std::string& why) { throw std::logic_error("node spec '" + s.type + "': " + why); };
  // Textures are fetched by name, `bypass` is the bypass pass's and `resolution` the
  // manifest's (codegen/manifest_build.cpp): none is the node's own to parse.
  auto own = [](const OptionSpec& o) {
    return o.kind != OptionSpec::Kind::Texture && o.name != kBypassOption && o.name != kResolutionOption;
  };
  bool readsAny = false;
  for (const auto& o : s.options) readsAny |= own(o);
  if (!s.parseOptions) {
    if (readsAny) fail("options without a parseOptions function");
    return;
  }
  nlohmann::json defaults = completeOptions(s, nlohmann::json::object());
  OptionReader reader(s, defaults);
  if (!s.parseOptions(reader)) fail("parseOptions returned nothing");
  for (const auto& o : s.options)
    if (own(o) && !reader.namesRead().count(o.name))
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
  for (const auto& [port, value] : hc.inputs) {
    int pi = ports.inputIndex(port);
    if (pi < 0) fail("no input '" + port + "'");
    if (ports.inputs[static_cast<size_t>(pi)].derived) fail("input '" + port + "' is derived by the node itself");
  }
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

// A quality knob's levels are valid, distinct values of the option, at least two.
static void checkLevels(const NodeSpec& s, const OptionSpec& o) {
  if (o.levels.empty()) return;
  auto fail = [&](const std::string& why) {
    throw std::logic_error("node spec '" + s.type + "': option '" + o.name + "': " + why);
  };
  if (o.levels.size() < 2) fail("a quality knob needs at least two levels");
  for (size_t i = 0; i < o.levels.size(); ++i) {
    std::string why = checkOption(o, o.levels[i], "");
    if (!why.empty()) fail("level " + o.levels[i].dump() + ": " + why);
    for (size_t j = 0; j < i; ++j)
      if (o.levels[j] == o.levels[i]) fail("level " + o.levels[i].dump() + " listed twice");
  }
}

// Every output is bypassed exactly once, by an input of its own fixed type or a constant
// of it.
static void checkBypass(const NodeSpec& s) {
  if (s.bypass.empty()) return;
  auto fail = [&](const std::string& why) { throw std::logic_error("node spec '" + s.type + "': bypass: " + why); };
  if (s.expand) fail("an expanding node has no op to bypass");
  for (const auto& out : s.outputs) {
    int count = 0;
    for (const auto& b : s.bypass) count += b.output == out.name;
    if (count != 1) fail("output '" + out.name + "' needs exactly one bypass value, has " + std::to_string(count));
    if (out.kind != PortKind::Fixed) fail("output '" + out.name + "' is not of a fixed type");
  }
  for (const auto& b : s.bypass) {
    int o = s.outputIndex(b.output);
    if (o < 0) fail("no output '" + b.output + "'");
    Type want = s.outputs[static_cast<size_t>(o)].type;
    if (b.constant.has_value() == !b.input.empty()) fail("output '" + b.output + "': an input or a constant, not both");
    if (b.constant && b.constant->type != want) fail("output '" + b.output + "': the constant is not of its type");
    if (!b.input.empty()) {
      int i = s.inputIndex(b.input);
      if (i < 0) fail("no input '" + b.input + "'");
      const PortSpec& in = s.inputs[static_cast<size_t>(i)];
      if (in.kind != PortKind::Fixed || in.type != want) fail("input '" + b.input + "' is not of the type of '" + b.output + "'");
    }
  }
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
  // Derived inputs (PortSpec::derived) are Fixed, without defaults, and named by derive.
  bool derives = false;
  for (const auto& p : s.inputs) {
    if (!p.derived) continue;
    derives = true;
    if (p.kind != PortKind::Fixed || p.defaultValue || p.defaultBuiltin)
      fail("derived input " + p.name + " must be Fixed and have no default");
  }
  if (derives != static_cast<bool>(s.derive)) fail(derives ? "derived inputs without a derive function" : "a derive function without derived inputs");
  if (derives && (s.expand || s.portsFor)) fail("derived inputs on an expanding node");
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
  for (const auto& o : s.options) checkLevels(s, o);
  checkBypass(s);
  checkOptionsParse(s);
  for (const auto& hc : s.hardCases) checkHardCaseNames(s, hc);
}

// What the bypass option's doc says the outputs become ("caustics = 0").
static std::string bypassText(const NodeSpec& s) {
  std::string text;
  for (const auto& b : s.bypass)
    text += (text.empty() ? "" : ", ") + b.output + " = " + (b.constant ? b.constant->toString() : "the input " + b.input);
  return text;
}

// The frame-sized scene resources a node reads ("scene_depth, scene_color"), for the
// resolution option's doc.
static std::string resourceList(const NodeSpec& s) {
  std::string text;
  for (SceneResource r : s.resources)
    if (r != SceneResource::Environment) text += (text.empty() ? "" : ", ") + std::string(sceneResourceRow(r).name);
  return text;
}

void Registry::add(NodeSpec spec) {
  if (!spec.bypass.empty()) {
    OptionSpec o;
    o.name = kBypassOption;
    o.kind = OptionSpec::Kind::Bool;
    o.defaultValue = false;
    o.doc = "switch the node off: " + bypassText(spec);
    o.levels = {true, false};
    spec.options.push_back(std::move(o));
  }
  const bool readsFrameSized = std::any_of(spec.resources.begin(), spec.resources.end(),
                                           [](SceneResource r) { return r != SceneResource::Environment; });
  if (readsFrameSized) {
    OptionSpec o;
    o.name = kResolutionOption;
    o.kind = OptionSpec::Kind::Number;
    o.defaultValue = 1.0;
    o.min = kMinResolution;
    o.max = 1.0;
    o.doc = "size of the scene passes this node reads (" + resourceList(spec) +
            "), as a fraction of the frame's width and height; a pass read by several nodes takes the smallest";
    for (double l : kResolutionLevels) o.levels.push_back(l);
    spec.options.push_back(std::move(o));
  }
  checkSpec(spec);
  std::string key = spec.type;
  if (specs_.count(key)) throw std::logic_error("node type registered twice: " + key);
  specs_.emplace(key, std::make_unique<NodeSpec>(std::move(spec)));
}

void Registry::addFileNodeType(std::string type, FileNodeMaker make) {
  if (specs_.count(type) || fileNodeTypes_.count(type)) throw std::logic_error("node type registered twice: " + type);
  fileNodeTypes_.emplace(std::move(type), std::move(make));
}

const FileNodeMaker* Registry::fileNodeType(std::string_view type) const {
  auto it = fileNodeTypes_.find(type);
  return it == fileNodeTypes_.end() ? nullptr : &it->second;
}

std::vector<std::string> Registry::fileNodeTypeNames() const {
  std::vector<std::string> out;
  for (const auto& [name, make] : fileNodeTypes_) out.push_back(name);
  return out;
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
