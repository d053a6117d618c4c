// Resolving, step 2: each node's type (registered, a function file, or an imported graph) and
// the options it writes, each checked against its type; PNG textures within the graph's
// texel budget and decodable.
#include <memory>
#include <string>

#include "core/file_node.h"
#include "core/graph_imports.h"
#include "core/graph_node_type.h"
#include "core/instance_options.h"
#include "core/node_options.h"
#include "core/png_decode.h"
#include "core/resolver.h"
#include "core/suggest.h"
#include "core/texture_check.h"

namespace wg::resolving {

std::string Resolver::acceptedTexture(const TextureFile& texture) {
  std::string why = chargeTextureBudget(texture);
  return why.empty() ? decodedTexture(texture) : why;
}

// The node type an imported function graph stands for: its parameters are the inputs
// (a parameter's default is the input's), its interface outputs the outputs.
const NodeSpec* Resolver::instanceSpec(const Import& im) {
  auto& slot = shared_.instanceSpecs[{im.graph.get(), im.name}];
  if (!slot) {
    auto spec = std::make_unique<NodeSpec>();
    spec->type = im.name;
    spec->family = "subgraph";
    spec->summary = im.graph->interface->description;
    NodePorts ports = interfacePorts(*im.graph);
    spec->inputs = std::move(ports.inputs);
    spec->outputs = std::move(ports.outputs);
    slot = std::move(spec);
  }
  return slot.get();
}

void Resolver::lookUpSpecs() {
  const size_t nodeCount = graph_.nodes.size();
  inputBase_.assign(nodeCount + 1, 0);
  for (size_t i = 0; i < nodeCount; ++i) inputBase_[i + 1] = inputBase_[i] + graph_.nodes[i].inputs.size();
  inputPort_.assign(inputBase_[nodeCount], -1);
  specs_.assign(graph_.nodes.size(), nullptr);
  ports_.resize(graph_.nodes.size());
  instanceOf_.assign(graph_.nodes.size(), nullptr);
  std::optional<NameSuggester> types;  // made on the first unknown type
  for (size_t i = 0; i < graph_.nodes.size(); ++i) {
    const Node& n = graph_.nodes[i];
    GraphNodeType type = nodeTypeOf(graph_, registry_, n.type);
    const NodeSpec* spec = type.spec;
    if (!spec && !type.import)
      if (const FileNodeMaker* make = registry_.fileNodeType(n.type)) {
        // Its ports come from its file: a file that does not pass is reported, and the
        // node is left out like an unknown type.
        auto made = (*make)({n, directory_, shared_.fileNodes++}, diags_);
        if (!made) continue;
        spec = keepFileNode(program_, std::move(*made));
      }
    if (type.import && type.import->graph) {
      spec = instanceSpec(*type.import);
      instanceOf_[i] = type.import;
      --program_.totalNodes;  // it stands for the nodes it inlines, which count instead
    }
    if (!spec) {
      if (!types) {
        std::vector<std::string> typeNames;
        for (const NodeSpec* s : registry_.all()) typeNames.push_back(s->type);
        for (const auto& im : graph_.imports) typeNames.push_back(im.name);
        types.emplace(std::move(typeNames));
      }
      diags_.error(DiagCode::UnknownNodeType, n.typeWhere,
                   "unknown node type '" + n.type + "'" + types->didYouMean(n.type), n.id);
      continue;
    }
    bool optionsValid = true;
    for (const auto& opt : n.options) {
      if (instanceOf_[i]) break;  // an instance's options are its interface's: bound when it is inlined
      int oi = spec->optionIndex(opt.name);
      if (oi < 0) {
        diags_.error(DiagCode::UnknownOption, opt.keyWhere,
                     "node type '" + spec->type + "' has no option '" + opt.name + "'" +
                         didYouMean(opt.name, namesOf(spec->options)),
                     n.id, optionLabel(opt.name));
        continue;
      }
      if (readsInterfaceTexture(spec->options[static_cast<size_t>(oi)], opt, n)) continue;
      TextureFile texture;
      std::string why = checkOption(spec->options[static_cast<size_t>(oi)], opt.value, directory_, &texture);
      if (why.empty()) why = chargeTextureBudget(texture);
      if (why.empty()) why = decodedTexture(texture);
      if (!why.empty()) {
        diags_.error(DiagCode::InvalidOption, opt.where, "option '" + opt.name + "' " + why, n.id,
                     optionLabel(opt.name));
        optionsValid = false;
      }
    }
    if (optionsValid && spec->checkOptions) reportOptionProblem(n, *spec);
    if (spec->portsFor) {
      // Its ports follow from its options: without valid options there are none to check
      // against (the options are reported), and the node is left out like an unknown type.
      if (!optionsValid) continue;
      ports_[i] = std::make_unique<NodePorts>(
          spec->portsFor(*parseOptions(*spec, completeOptions(*spec, declaredOptions(n, *spec)))));
    }
    specs_[i] = spec;
    const std::vector<PortSpec>& inputs = inputsOf(i);
    for (size_t k = 0; k < n.inputs.size(); ++k) {
      const NodeInput& in = n.inputs[k];
      int pi = portIndex(inputs, in.port);
      inputPort_[inputBase_[i] + k] = pi;
      // A derived input is the node's own (NodeSpec::derive): not a port of the file.
      if (pi >= 0 && inputs[static_cast<size_t>(pi)].derived)
        diags_.error(DiagCode::UnknownInputPort, in.keyWhere,
                     "input '" + in.port + "' of node type '" + spec->type +
                         "' is computed by the node itself and cannot be connected",
                     n.id, inputLabel(in.port));
      else if (pi < 0)
        diags_.error(DiagCode::UnknownInputPort, in.keyWhere,
                     "node type '" + spec->type + "' has no input '" + in.port + "'" +
                         didYouMean(in.port, namesOf(inputs)),
                     n.id, inputLabel(in.port));
    }
  }
}

// A texture option written "$name" samples the interface texture `name` (checked where
// it was chosen); true when `opt` is one, after reporting one that is not declared.
bool Resolver::readsInterfaceTexture(const OptionSpec& spec, const NodeOption& opt, const Node& n) {
  if (spec.kind != OptionSpec::Kind::Texture) return false;
  auto name = interfaceTextureReference(opt.value);
  if (!name) return false;
  if (!options_ || !options_->textures.count(*name))
    diags_.error(DiagCode::InstanceOptionUnknown, opt.where,
                 "option '" + opt.name + "' reads the interface texture '" + std::string(*name) + "', but " +
                     (graph_.interface ? "the interface declares no texture option of that name"
                                       : "the graph has no interface (only a function graph's nodes read one)"),
                 idOf(n), optionLabel(opt.name));
  return true;
}

// Options each valid alone but meaningless together (NodeSpec::checkOptions), reported
// at the option blamed, or at the node when the file leaves that option at its default.
void Resolver::reportOptionProblem(const Node& n, const NodeSpec& spec) {
  auto problem = spec.checkOptions(*parseOptions(spec, completeOptions(spec, declaredOptions(n, spec))));
  if (!problem) return;
  SourceRef at = n.where;
  for (const auto& o : n.options)
    if (o.name == problem->option) at = o.where;
  diags_.error(DiagCode::InvalidOption, at, "option '" + problem->option + "' " + problem->why, n.id,
               optionLabel(problem->option));
}

// The options a node writes that its type declares (the others are reported).
nlohmann::json Resolver::declaredOptions(const Node& node, const NodeSpec& spec) {
  nlohmann::json written = writtenOptions(node);
  for (const auto& o : node.options)
    if (spec.optionIndex(o.name) < 0) written.erase(o.name);
  return written;
}

// A PNG file whose header passed must decode too (a broken zlib stream, too few
// pixels): found by validate, not first by render. After the budget, so a file the
// budget refuses is not decoded. Builtin textures (no file) pass.
std::string Resolver::decodedTexture(const TextureFile& texture) {
  if (texture.realPath.empty()) return "";
  std::string why = checkPngDecodes(texture.realPath);
  return why.empty() ? "" : "is not usable: cannot decode texture '" + texture.realPath + "': " + why;
}

// All of a graph's PNG textures together stay within kMaxGraphTextureTexels (each file
// counted once, however many nodes sample it): "" or why the one that overflows it is refused.
std::string Resolver::chargeTextureBudget(const TextureFile& texture) {
  if (texture.realPath.empty() || !shared_.texturesCounted.insert(texture.realPath).second) return "";
  shared_.textureTexels += texture.width * texture.height;
  if (shared_.textureTexels <= kMaxGraphTextureTexels) return "";
  return "is not usable: the graph's PNG textures would hold " + std::to_string(shared_.textureTexels) +
         " texels together; the limit per graph is " + std::to_string(kMaxGraphTextureTexels);
}

}  // namespace wg::resolving
