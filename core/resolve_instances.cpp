// Resolving a subgraph instance: the imported graph's nodes resolved into the same
// program under the instance's id, its parameters reading the instance's inputs, its
// texture paths and interface textures retargeted.
#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>

#include "core/color_parameters.h"
#include "core/instance_options.h"
#include "core/number_format.h"
#include "core/resolver.h"
#include "core/sampler_state.h"
#include "core/texture_check.h"

namespace wg::resolving {

// A subgraph instance: the imported graph's nodes resolved into this program with its
// parameters reading the instance's inputs, as if written out here. Its faults are
// reported where they are in its file, with a note naming this instance.
void Resolver::inlineInstance(int ni, const Op& op, const std::vector<Type>& sourceTypes,
                    const std::vector<const NodeInput*>& given) {
  const Node& node = graph_.nodes[static_cast<size_t>(ni)];
  const Import& im = *instanceOf_[static_cast<size_t>(ni)];
  const Graph& sub = *im.graph;
  auto inputs = convertedInputs(node, op, op.spec->inputs, sourceTypes, given);
  if (!inputs) return;
  InstanceScope scope;
  scope.idPrefix = idOf(node) + "/";
  auto chain = std::make_shared<std::vector<LocatedNote>>();
  LocatedNote here{node.where, "in instance '" + idOf(node) + "' of '" + im.path + "'", idOf(node)};
  chain->push_back(here);
  if (scope_ && scope_->chain) chain->insert(chain->end(), scope_->chain->begin(), scope_->chain->end());
  scope.chain = std::move(chain);
  bool inRange = true;
  for (size_t pi = 0; pi < sub.parameters.size(); ++pi) {
    const Parameter& p = sub.parameters[pi];
    const ValueRef& v = (*inputs)[pi];
    if (v.kind == ValueRef::Kind::Const && !fitsRange(v.constant(), p)) {
      diags_.error(DiagCode::InterfaceMismatch, portWhere(node, given[pi]),
                   "input '" + p.name + "' of '" + im.name + "' is " + v.constant().toString() +
                       ", outside its range " + rangeText(p),
                   idOf(node), inputLabel(p.name));
      inRange = false;
    }
    bool literal = !given[pi] || given[pi]->source.kind == InputSource::Kind::Literal;
    scope.inputs.emplace(p.name, isColorHint(p.hint) && literal && v.kind == ValueRef::Kind::Const ? linearised(v) : v);
  }
  InstanceOptionRequest request{*sub.interface, sub.file, &node, idOf(node), graph_.file, shared_.topDirectory,
                                [this](const TextureFile& t) { return acceptedTexture(t); }};
  auto bound = bindInstanceOptions(request, diags_);
  if (!inRange || !bound) return;
  scope.options = std::move(*bound);
  size_t firstDiag = diags_.all().size();
  size_t firstOp = program_.ops.size();
  bool ok = Resolver(withInstanceOptions(sub, scope.idPrefix), registry_, diags_, program_, shared_, scope).runInstance();
  diags_.addLocatedNoteFrom(firstDiag, here);
  if (!ok) {
    program_.ops.resize(firstOp);
    return;
  }
  expandedOutputs_[static_cast<size_t>(ni)] = std::move(scope.outputs);
}

// The subgraph an instance inlines: `sub` as written, or, where options of its own nodes
// are set from outside (Graph::instanceOptions of the top-level graph, qualified by
// `prefix`), a copy with them in place, kept for the program's lifetime of this resolve.
const Graph& Resolver::withInstanceOptions(const Graph& sub, const std::string& prefix) {
  if (!shared_.instanceOptions) return sub;
  Graph* copy = nullptr;
  for (const InstanceOption& o : *shared_.instanceOptions) {
    if (o.node.size() <= prefix.size() || o.node.compare(0, prefix.size(), prefix) != 0) continue;
    std::string id = o.node.substr(prefix.size());
    if (id.find('/') != std::string::npos) continue;  // deeper: the nested instance's business
    if (!copy) copy = &shared_.instanceGraphs.emplace_back(sub);
    for (auto& n : copy->nodes) {
      if (n.id != id) continue;
      auto written = std::find_if(n.options.begin(), n.options.end(), [&](const NodeOption& w) { return w.name == o.option.name; });
      if (written == n.options.end())
        n.options.push_back(o.option);
      else
        *written = o.option;
    }
  }
  return copy ? *copy : sub;
}

bool Resolver::fitsRange(const Value& v, const Parameter& p) {
  for (int k = 0; k < componentCount(v.type); ++k)
    if ((p.min && v[k] < *p.min) || (p.max && v[k] > *p.max)) return false;
  return true;
}

std::string Resolver::rangeText(const Parameter& p) {
  return "[" + (p.min ? formatNumber(*p.min) : std::string("-inf")) + ", " +
         (p.max ? formatNumber(*p.max) : std::string("inf")) + "]";
}

// A PNG path in a subgraph is relative to the subgraph's file; the program reads every
// texture relative to the top-level graph's folder (the import check keeps the
// subgraph inside it, so the path needs no "..").
void Resolver::retargetTexturePaths(const NodeSpec& spec, nlohmann::json& options) const {
  for (const auto& o : spec.options) {
    if (o.kind != OptionSpec::Kind::Texture) continue;
    auto it = options.find(o.name);
    if (it == options.end() || !it->is_string()) continue;
    const std::string& path = it->get_ref<const std::string&>();
    if (path.rfind(kBuiltinTexturePrefix, 0) == 0 || interfaceTextureReference(*it)) continue;
    namespace fs = std::filesystem;
    fs::path top = shared_.topDirectory.empty() ? fs::path(".") : fs::path(shared_.topDirectory);
    fs::path here = directory_.empty() ? fs::path(".") : fs::path(directory_);
    *it = (here / path).lexically_normal().lexically_relative(top.lexically_normal()).generic_string();
  }
}

// Texture options written "$name" become the texture the instance chose, and the sampler
// state it set becomes the node's (its wrap, filter and colour space options); a node
// without those options samples in its own fixed state, so setting one for it is refused.
bool Resolver::bindInterfaceTextures(const NodeSpec& spec, const Node& node, nlohmann::json& options) {
  bool ok = true;
  for (const auto& o : spec.options) {
    if (o.kind != OptionSpec::Kind::Texture) continue;
    auto it = options.find(o.name);
    if (it == options.end()) continue;
    auto reference = interfaceTextureReference(*it);
    if (!reference) continue;
    // A copy: the view points into the option's string, which the next line replaces.
    const std::string name{*reference};
    const BoundTexture& bound = options_->textures.find(name)->second;  // lookUpSpecs checked it
    *it = bound.texture.source;
    auto set = [&](std::string_view key, const auto& value, auto nameOf) {
      if (!value) return;
      if (spec.optionIndex(key) < 0) {
        diags_.error(DiagCode::InstanceOptionValue, bound.where,
                     "the texture '" + name + "' sets '" + std::string(key) + "', but node '" + idOf(node) +
                         "' (" + spec.type + ") that samples it has no such option: it samples in its own fixed state",
                     idOf(node), optionLabel(o.name));
        ok = false;
        return;
      }
      options[std::string(key)] = std::string(nameOf(*value));
    };
    set("wrap", bound.texture.wrap, wrapName);
    set("filter", bound.texture.filter, filterName);
    set("color_space", bound.texture.colorSpace, colorSpaceName);
  }
  return ok;
}

}  // namespace wg::resolving
