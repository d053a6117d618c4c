#include "accuracy/node_probe.h"

#include "accuracy/gpu_executor.h"
#include "core/node_options.h"

namespace wg::accuracy {
namespace {

const Value* findInput(const ProbeCase& c, const std::string& port) {
  for (const auto& [name, value] : c.inputs)
    if (name == port) return &value;
  return nullptr;
}

}  // namespace

NodeProbeSetup makeNodeProbe(const NodeSpec& spec, const nlohmann::json& options, const std::vector<ProbeCase>& cases) {
  NodeProbeSetup setup;
  Graph& g = setup.graph;
  g.file = "node '" + spec.type + "'";
  g.name = "probe_" + spec.type;
  Node node;
  node.id = "n";
  node.type = spec.type;
  for (auto it = options.begin(); it != options.end(); ++it)
    if (it.key() != kOceanOptionsKey) node.options.push_back({it.key(), it.value(), {}, {}});
  const std::vector<PortSpec> inputs = portsOfNode(spec, options).inputs;  // an expression's follow from its options
  // An `ocean` input carries no value a parameter could hold: an ocean_spectrum node feeds it.
  for (const PortSpec& port : inputs) {
    if (port.kind != PortKind::Fixed || port.type != Type::Ocean) continue;
    Node sea;
    sea.id = "sea";
    sea.type = "ocean_spectrum";
    auto given = options.find(kOceanOptionsKey);
    if (given != options.end() && given->is_object())
      for (auto it = given->begin(); it != given->end(); ++it) sea.options.push_back({it.key(), it.value(), {}, {}});
    g.nodes.push_back(sea);
    NodeInput in;
    in.port = port.name;
    in.source.kind = InputSource::Kind::NodeOutput;
    in.source.name = sea.id;
    in.source.port = "ocean";
    node.inputs.push_back(in);
  }

  // The type of each input parameter: the port's own, or (Gen, Custom) the first value given.
  std::vector<Type> paramType(inputs.size(), Type::Invalid);
  for (size_t k = 0; k < inputs.size(); ++k) {
    const PortSpec& port = inputs[k];
    if (port.kind == PortKind::Fixed && port.type == Type::Ocean) continue;  // fed by a node above
    if (port.kind == PortKind::Fixed) {
      bool given = false;
      for (const auto& c : cases) given |= findInput(c, port.name) != nullptr;
      if (given || port.required()) paramType[k] = port.type;
      continue;
    }
    for (const auto& c : cases)
      if (const Value* v = findInput(c, port.name); v && paramType[k] == Type::Invalid) paramType[k] = v->type;
    if (paramType[k] == Type::Invalid && port.required()) paramType[k] = port.kind == PortKind::Custom ? Type::Vec3 : Type::Float;
  }
  for (size_t k = 0; k < inputs.size(); ++k) {
    if (paramType[k] == Type::Invalid) continue;
    Parameter p;
    p.name = "in_" + inputs[k].name;
    p.type = paramType[k];
    p.defaultValue.assign(static_cast<size_t>(componentCount(p.type)), 0.5);
    g.parameters.push_back(p);
    NodeInput in;
    in.port = inputs[k].name;
    in.source.kind = InputSource::Kind::Parameter;
    in.source.name = p.name;
    node.inputs.push_back(in);
  }
  g.nodes.push_back(node);
  GraphOutput out;
  out.slot = OutputSlot::FragmentAlpha;  // resolve wants one; the probe output replaces it
  out.source.kind = InputSource::Kind::Literal;
  out.source.literal = {0.0};
  g.outputs.push_back(out);

  setup.cases.file = g.file;
  for (const auto& c : cases) {
    ProbeCase pc = c;
    pc.parameters.clear();
    bool fits = true;
    for (size_t k = 0; k < inputs.size(); ++k) {
      if (paramType[k] == Type::Invalid) continue;
      const PortSpec& port = inputs[k];
      Value v = Value::ofType(paramType[k], 0.5);
      if (const Value* given = findInput(c, port.name)) {
        if (given->type != paramType[k] && given->type != Type::Float) fits = false;
        if (port.kind == PortKind::Fixed && given->type != port.type && given->type != Type::Float) fits = false;
        v = given->convertedTo(paramType[k]);
      } else if (port.defaultValue) {
        v = port.defaultValue->convertedTo(paramType[k]);
      } else if (port.defaultBuiltin) {
        Value b = c.env.builtin(*port.defaultBuiltin);
        if (b.type == paramType[k] || b.type == Type::Float) v = b.convertedTo(paramType[k]);
      }
      pc.parameters.emplace_back("in_" + port.name, toFloat32(v));
    }
    pc.inputs.clear();
    if (fits) setup.cases.cases.push_back(std::move(pc));
    else setup.skipped.push_back(c.name);
  }
  return setup;
}

std::optional<ProbeReport> probeNode(const NodeSpec& spec, const nlohmann::json& options, const std::string& output,
                                     const std::vector<ProbeCase>& cases, Target target, Diagnostics& diags,
                                     const ShaderMutation& mutation) {
  return probeNode(spec, options, output, cases, *currentGlExecutor(target), diags, mutation);
}

std::optional<ProbeReport> probeNode(const NodeSpec& spec, const nlohmann::json& options, const std::string& output,
                                     const std::vector<ProbeCase>& cases, GpuExecutor& executor, Diagnostics& diags,
                                     const ShaderMutation& mutation) {
  NodeProbeSetup setup = makeNodeProbe(spec, options, cases);
  if (setup.cases.cases.empty()) return ProbeReport{};
  ProbeOutput out{"n", output.empty() ? portsOfNode(spec, options).outputs.at(0).name : output};
  // The node-probe keys are spent here (options chose the graph; ranges apply below).
  ProbeCaseFile graphCases = setup.cases;
  for (auto& c : graphCases.cases) {
    c.options = nlohmann::json::object();
    c.ranges.clear();
    c.nodes.clear();
  }
  auto report = probeGraph(setup.graph, out, graphCases, executor, diags, mutation);
  if (report) {
    report->graph = spec.type;
    report->output = spec.type + "." + out.port;
    // A case's range for this output ("type.port") applies too.
    for (size_t i = 0; i < report->cases.size(); ++i) {
      const ProbeCase& c = setup.cases.cases[i];
      auto r = c.ranges.find(report->output);
      if (r == c.ranges.end()) continue;
      ProbeCaseResult& res = report->cases[i];
      res.range = r->second;
      for (int k = 0; k < res.components; ++k) {
        double g = res.gpu[static_cast<size_t>(k)], e = res.reference[static_cast<size_t>(k)];
        res.inRange &= withinRange(g, r->second, res.tolerance) && withinRange(e, r->second, res.tolerance);
      }
    }
  }
  return report;
}

}  // namespace wg::accuracy
