#include "accuracy/function_sweep.h"

#include <cmath>
#include <set>
#include <stdexcept>

#include "accuracy/gpu_executor.h"
#include "accuracy/node_probe.h"
#include "accuracy/number_text.h"
#include "codegen/emit_glsl.h"
#include "codegen/probe_program.h"
#include "core/resolve.h"
#include "core/texture_check.h"
#include "nodes/glsl_function_node.h"
#include "nodes/registry.h"

namespace wg::accuracy {
namespace {

// The value an input not being swept keeps, as node probes give a required input no case
// sets (accuracy/node_probe.h).
constexpr double kHeldInput = 0.5;

std::string valueText(const Value& v) {
  std::string s;
  for (int i = 0; i < v.size(); ++i) s += (i ? ", " : "") + significantDigits(v[i], 6);
  return v.size() == 1 ? s : "(" + s + ")";
}

std::string gpuText(const std::array<double, 4>& gpu, int components) {
  std::string s;
  for (int i = 0; i < components; ++i) s += (i ? ", " : "") + significantDigits(gpu[static_cast<size_t>(i)], 6);
  return s;
}

// The options the probe node is made with: the function and its reference as written,
// every sampler at the built-in texture the node names, else at its option's default (a
// built-in one), so the sweep does not depend on the PNGs beside a graph or an instance's.
nlohmann::json sweptOptions(const NodeSpec& spec, const nlohmann::json& complete) {
  nlohmann::json o = nlohmann::json::object();
  for (const OptionSpec& option : spec.options) {
    auto it = complete.find(option.name);
    if (option.kind == OptionSpec::Kind::Texture) {
      bool builtin = it != complete.end() && it->is_string() && it->get_ref<const std::string&>().starts_with(kBuiltinTexturePrefix);
      o[option.name] = builtin ? *it : option.defaultValue;
    }
    else if (option.name == "reference") {
      if (it != complete.end() && it->is_object() && !it->empty()) o[option.name] = *it;
    } else if (it != complete.end()) {
      o[option.name] = *it;
    }
  }
  return o;
}

// What one case of the sweep sets: the port and the class it takes.
struct SweptInput {
  std::string port;
  FunctionInputClass inputClass;
};

// One case per (input port, class), named "port=class", the other inputs held; `swept`
// gets what each case sets.
std::vector<ProbeCase> functionSweepCases(const NodeSpec& spec, const ProbeCaseFile& suite, std::vector<SweptInput>& swept) {
  std::vector<ProbeCase> cases;
  for (const PortSpec& port : spec.inputs) {
    for (FunctionInputClass& k : functionInputClasses(suite, port.type)) {
      ProbeCase c;
      c.name = port.name + "=" + k.name;
      c.env = defaultProbeEnvironment();
      for (const PortSpec& other : spec.inputs)
        c.inputs.emplace_back(other.name, other.name == port.name ? k.value : Value::ofType(other.type, kHeldInput));
      cases.push_back(std::move(c));
      swept.push_back({port.name, std::move(k)});
    }
  }
  return cases;
}

// The per-case GPU results of one output with no reference: the probe shader run on the
// executor, nothing evaluated in double.
std::vector<std::array<float, 4>> gpuOnly(const Graph& graph, const ProbeOutput& output, const ProbeCaseFile& cases,
                                          GpuExecutor& executor, Diagnostics& diags, int& components) {
  auto program = buildProbeProgram(graph, defaultRegistry(), output, diags);
  if (!program) return {};
  components = componentCount(program->outputs.front().type);
  EmitResult shader = emitProgram(*program, executor.target(), graph.file, EmitMode::Probe);
  return executor.runProbe(shader, *program, cases.cases,
                           graph.file + " (function sweep, " + std::string(targetName(executor.target())) + ")");
}

}  // namespace

std::vector<FunctionInputClass> functionInputClasses(const ProbeCaseFile& suite, Type t) {
  std::vector<FunctionInputClass> out;
  auto add = [&](std::string name, const Value& v) {
    if (!v.allFinite()) return;
    for (const auto& c : out)
      if (c.value == v) return;
    out.push_back({std::move(name), v});
  };
  for (const auto& c : suite.cases)
    for (const auto& [port, value] : c.inputs)
      if (value.type == t) add(c.name + "." + port, toFloat32(value));
  if (t != Type::Float && componentCount(t) > 1)
    for (const auto& c : suite.cases)
      for (const auto& [port, value] : c.inputs)
        if (value.type == Type::Float) add(c.name + "." + port + " splat", toFloat32(value).convertedTo(t));
  return out;
}

std::optional<std::vector<FunctionNodeUnderTest>> functionNodesOf(const Graph& graph, Diagnostics& diags) {
  auto program = resolveGraph(graph, defaultRegistry(), diags);
  if (!program) return std::nullopt;
  std::vector<FunctionNodeUnderTest> out;
  std::set<std::string> seen;
  for (const Op& op : program->ops) {
    if (!op.spec || op.spec->type != kGlslFunctionType) continue;
    FunctionNodeUnderTest node;
    node.graphFile = op.where.file.str();
    node.options = sweptOptions(*op.spec, op.options());
    // Two instances of one subgraph hold the same node (its id prefixed by each instance's):
    // the same place in the same file, with the same options, is swept once.
    std::string key = node.graphFile + ":" + std::to_string(op.where.line) + ":" + std::to_string(op.where.col) + "\n" +
                      node.options.dump();
    if (!seen.insert(key).second) continue;
    for (const auto& kept : program->fileNodeSpecs)
      if (kept.get() == op.spec) node.spec = kept;
    node.hasReference = node.options.contains("reference");
    node.label = "node '" + op.nodeId + "' (" + node.graphFile + ", function '" +
                 node.options.value("function", std::string()) + "')";
    out.push_back(std::move(node));
  }
  return out;
}

FunctionSweepResult sweepFunctionNodes(const std::vector<FunctionNodeUnderTest>& nodes, const ProbeCaseFile& suite,
                                       GpuExecutor& executor) {
  FunctionSweepResult result;
  result.target = executor.target();
  const std::string target(targetName(result.target));
  for (const FunctionNodeUnderTest& node : nodes) {
    ++result.nodes;
    const NodeSpec& spec = *node.spec;
    std::vector<SweptInput> swept;
    std::vector<ProbeCase> cases = functionSweepCases(spec, suite, swept);
    if (!node.hasReference)
      result.notes.push_back(node.label + " has no double reference: its outputs are checked for NaN and Inf only");
    for (const OptionSpec& option : spec.options)
      if (option.kind == OptionSpec::Kind::Texture)
        result.notes.push_back(node.label + ": sampler2D '" + option.name + "' is held at the texture " +
                               node.options.value(option.name, std::string()) + ", not swept");
    if (cases.empty()) {
      result.notes.push_back(node.label + " has no input the suite gives a value class for: nothing swept");
      continue;
    }
    NodeProbeSetup setup = makeNodeProbe(spec, node.options, cases);
    setup.graph.file = node.graphFile;  // the node's .glsl file is named relative to this graph
    for (const PortSpec& out : spec.outputs) {
      if (!isFloatScalarOrVector(out.type)) {  // a probe reads one RGBA pixel per case
        result.notes.push_back(node.label + ": output '" + out.name + "' is a " + std::string(typeName(out.type)) +
                               ", which a probe pixel cannot hold: not read back");
        continue;
      }
      Diagnostics diags;
      ProbeOutput output{"n", out.name};
      std::vector<std::array<float, 4>> gpu;
      std::optional<ProbeReport> report;
      int components = 1;
      if (node.hasReference) {
        report = probeGraph(setup.graph, output, setup.cases, executor, diags);
        if (report) {
          components = report->cases.empty() ? 1 : report->cases.front().components;
          for (const auto& c : report->cases) {
            std::array<float, 4> g{};
            for (size_t i = 0; i < 4; ++i) g[i] = static_cast<float>(c.gpu[i]);
            gpu.push_back(g);
          }
        }
      } else {
        gpu = gpuOnly(setup.graph, output, setup.cases, executor, diags, components);
      }
      if (gpu.size() != cases.size()) {
        std::string why;
        for (const auto& d : diags.all()) why += " " + formatText(d);
        result.errors.push_back(target + " " + node.label + " output '" + out.name + "':" +
                                (why.empty() ? " the GPU returned " + std::to_string(gpu.size()) + " of " +
                                                   std::to_string(cases.size()) + " results"
                                             : why));
        continue;
      }
      for (size_t i = 0; i < cases.size(); ++i) {
        FunctionSweepCase c;
        c.node = node.label;
        c.output = out.name;
        c.port = swept[i].port;
        c.inputClass = swept[i].inputClass.name;
        c.input = swept[i].inputClass.value;
        c.components = components;
        bool finite = true;
        for (int k = 0; k < components; ++k) {
          c.gpu[static_cast<size_t>(k)] = gpu[i][static_cast<size_t>(k)];
          finite &= std::isfinite(gpu[i][static_cast<size_t>(k)]);
        }
        if (report) {
          c.compared = true;
          c.failure = report->cases[i].failure();
          c.nanInf = !report->cases[i].gpuFinite || !report->cases[i].referenceFinite;
          c.absError = report->cases[i].absError;
          c.bound = report->cases[i].bound;
          double ratio = c.bound > 0 ? c.absError / c.bound : (c.absError > 0 ? INFINITY : 0);
          if (ratio > result.worstErrorToBound || result.worstCase.empty()) {
            result.worstErrorToBound = ratio;
            result.worstCase = node.label + " output '" + c.output + "' " + c.port + "=" + c.inputClass;
          }
        } else if (!finite) {
          c.failure = "GPU NaN/Inf";
          c.nanInf = true;
        }
        ++result.caseRuns;
        result.compared += c.compared ? 1 : 0;
        if (!c.failure.empty()) {
          ++result.failures;
          result.nanInf += c.nanInf ? 1 : 0;
          result.failureLines.push_back(target + " " + node.label + " output '" + c.output + "', port '" + c.port +
                                        "' case '" + c.inputClass + "' " + valueText(c.input) + ": " + c.failure +
                                        " (gpu " + gpuText(c.gpu, components) + ")");
        }
        result.cases.push_back(std::move(c));
      }
    }
  }
  return result;
}

std::string formatFunctionSweep(const FunctionSweepResult& r) {
  std::string out;
  for (const auto& n : r.notes) out += "note: " + n + "\n";
  for (const auto& f : r.failureLines) out += "FAIL " + f + "\n";
  for (const auto& e : r.errors) out += "error: " + e + "\n";
  out += std::to_string(r.nodes) + " function node" + (r.nodes == 1 ? "" : "s") + " on " +
         std::string(targetName(r.target)) + ": " + std::to_string(r.caseRuns) + " case runs (" +
         std::to_string(r.compared) + " compared with a reference), " + std::to_string(r.failures) + " failed (" +
         std::to_string(r.nanInf) + " NaN/Inf)\n";
  if (r.compared > 0)
    out += "  worst error/bound " + significantDigits(r.worstErrorToBound, 3) + " at " + r.worstCase + "\n";
  return out;
}

}  // namespace wg::accuracy
