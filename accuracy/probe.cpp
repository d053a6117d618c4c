#include "accuracy/probe.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "accuracy/error_bound.h"
#include "accuracy/number_text.h"
#include "accuracy/gpu_executor.h"
#include "codegen/cpu_backend.h"
#include "codegen/emit_glsl.h"
#include "core/number_format.h"
#include "core/registry.h"
#include "nodes/registry.h"
#include "runtime/runtime_error.h"

namespace wg::accuracy {
namespace {

std::string fmtShort(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2e", x);
  return buf;
}

std::string vectorText(const std::array<double, 4>& v, int n) {
  if (n == 1) return significantDigits(v[0], 9);
  std::string s = "(";
  for (int i = 0; i < n; ++i) s += (i ? ", " : "") + significantDigits(v[static_cast<size_t>(i)], 9);
  return s + ")";
}

nlohmann::json number(double x) {
  if (std::isfinite(x)) return x;
  return std::isnan(x) ? "nan" : (x > 0 ? "inf" : "-inf");
}

}  // namespace

// A float32 result cannot equal every double bound (1e30 rounds up): the range allows the
// tolerance's slack.
bool withinRange(double x, const std::pair<double, double>& range, double tolerance) {
  return x >= range.first - tolerance * std::max(1.0, std::abs(range.first)) &&
         x <= range.second + tolerance * std::max(1.0, std::abs(range.second));
}

namespace {

ProbeCaseResult compare(const ProbeCase& c, const std::array<float, 4>& gpu, const Value& ref, double tolerance,
                        const std::array<double, 4>& conditioning) {
  ProbeCaseResult r;
  r.name = c.name;
  r.expect = c.expect;
  r.components = ref.size();
  r.tolerance = tolerance;
  r.range = c.range;
  for (int i = 0; i < r.components; ++i) {
    auto k = static_cast<size_t>(i);
    double g = gpu[k], e = ref[i];
    r.gpu[k] = g;
    r.reference[k] = e;
    r.gpuFinite &= std::isfinite(g);
    r.referenceFinite &= std::isfinite(e);
    if (c.range) r.inRange &= withinRange(g, *c.range, tolerance) && withinRange(e, *c.range, tolerance);
    double abs = std::abs(g - e);
    if (!std::isfinite(g) || !std::isfinite(e)) abs = std::numeric_limits<double>::infinity();
    double rel = abs == 0 ? 0 : (e != 0 ? abs / std::abs(e) : std::numeric_limits<double>::infinity());
    double bound = tolerance * std::max(1.0, std::abs(e)) + conditioning[k];
    // The component that comes closest to its bound (or passes it) is the one reported.
    double excess = abs - bound;
    if (i == 0 || excess > r.absError - r.bound || std::isnan(abs)) {
      r.absError = abs, r.relError = rel, r.bound = bound, r.conditioning = conditioning[k];
    }
    r.withinTolerance &= abs <= bound;
  }
  return r;
}

}  // namespace

std::string ProbeCaseResult::failure() const {
  if (!gpuFinite) return "GPU NaN/Inf";
  if (!referenceFinite) return "reference NaN/Inf";
  if (!inRange) return "outside [" + significantDigits(range->first, 9) + ", " + significantDigits(range->second, 9) + "]";
  if (!withinTolerance)
    return "error " + fmtShort(absError) + " > bound " + fmtShort(bound) + " (tolerance " + fmtShort(tolerance) +
           ", conditioning " + fmtShort(conditioning) + ")";
  return "";
}

bool ProbeReport::passed() const { return failures() == 0; }
int ProbeReport::failures() const {
  return static_cast<int>(std::count_if(cases.begin(), cases.end(), [](const ProbeCaseResult& c) { return !c.passed(); }));
}

bool mutateText(std::string& text, const ShaderMutation& m) {
  if (!m.active()) return false;
  if (m.find.find('\n') != std::string::npos || m.replace.find('\n') != std::string::npos)
    throw std::invalid_argument("a shader mutation edits within one line");
  bool found = false;
  for (size_t at = text.find(m.find); at != std::string::npos; at = text.find(m.find, at + m.replace.size())) {
    text.replace(at, m.find.size(), m.replace);
    found = true;
  }
  return found;
}

void applyMutation(EmitResult& shader, const ShaderMutation& m) {
  if (!m.active()) return;
  bool found = false;
  for (auto& stage : shader.shaders) found |= mutateText(stage.text, m);
  if (!found) throw std::invalid_argument("the mutation's text '" + m.find + "' is not in the probe shader");
}

std::optional<ProbeReport> probeGraph(const Graph& graph, const ProbeOutput& output, const ProbeCaseFile& cases,
                                      Target target, Diagnostics& diags, const ShaderMutation& mutation) {
  return probeGraph(graph, output, cases, *currentGlExecutor(target), diags, mutation);
}

std::optional<ProbeReport> probeGraph(const Graph& graph, const ProbeOutput& output, const ProbeCaseFile& cases,
                                      GpuExecutor& executor, Diagnostics& diags, const ShaderMutation& mutation) {
  // Parameters a case sets must exist in the graph (they may be pruned from the program).
  for (const auto& c : cases.cases) {
    // The node-probe keys have no meaning for a graph: say which keys a graph case takes.
    std::string nodeKeys;
    if (!c.inputs.empty()) nodeKeys += " \"inputs\"";
    if (!c.options.empty()) nodeKeys += " \"options\"";
    if (!c.ranges.empty()) nodeKeys += " \"ranges\"";
    if (!c.nodes.empty()) nodeKeys += " \"nodes\"";
    if (!nodeKeys.empty())
      diags.error(DiagCode::InvalidProbeCases, c.where,
                  "case '" + c.name + "' sets" + nodeKeys +
                      ", which only node probes (--node) take; a graph case takes name, expect, region, the builtins "
                      "(uv, world_position, normal, view_direction, camera_position, time, screen_uv, frag_depth, "
                      "near_far, sun_direction), camera, view, projection, scene, parameters, range and tolerance");
    for (const auto& [name, value] : c.parameters) {
      const Parameter* p = graph.findParameter(name);
      if (!p) {
        std::vector<std::string> names;
        for (const auto& q : graph.parameters) names.push_back(q.name);
        diags.error(DiagCode::InvalidProbeCases, c.where,
                    "case '" + c.name + "' sets parameter '" + name + "', which " + graph.file + " does not declare");
      } else if (p->isStatic) {
        diags.error(DiagCode::InvalidProbeCases, c.where,
                    "case '" + c.name + "' sets parameter '" + name + "', which is static (compiled into the shader)");
      } else if (value.type != p->type && value.type != Type::Float) {
        diags.error(DiagCode::InvalidProbeCases, c.where,
                    "case '" + c.name + "' gives parameter '" + name + "' a " + std::string(typeName(value.type)) +
                        ", but it is a " + std::string(typeName(p->type)));
      }
    }
  }
  if (diags.hasErrors()) return std::nullopt;
  auto program = buildProbeProgram(graph, defaultRegistry(), output, diags);
  if (!program) return std::nullopt;
  std::optional<EmitResult> probeShader = executor.probeShader(*program, graph.file, diags);
  if (!probeShader) return std::nullopt;
  EmitResult& shader = *probeShader;
  applyMutation(shader, mutation);

  ErrorModel model = programErrorModel(*program);
  if (cases.tolerance) model.tolerance = *cases.tolerance;
  std::vector<BuiltinUniform> perturbed;  // the builtins the shader reads as float32 uniforms
  for (const auto& u : shader.uniforms)
    if (u.parameter < 0) perturbed.push_back(u.builtin);

  ProbeReport report;
  report.graph = graph.file;
  report.output = std::string(outputSlotName(OutputSlot::FragmentColor));
  if (!output.node.empty()) {
    std::string port = output.port;
    if (port.empty())
      if (const Node* n = graph.findNode(output.node))
        if (const NodeSpec* spec = defaultRegistry().find(n->type); spec && !spec->outputs.empty()) port = spec->outputs[0].name;
    report.output = output.node + "." + port;
  }
  report.type = program->outputs.front().type;
  report.target = executor.targetLabel();
  report.renderer = executor.deviceName();
  std::vector<std::array<float, 4>> gpu =
      executor.runProbe(shader, *program, cases.cases, graph.file + " (probe, " + report.target + ")");
  for (size_t i = 0; i < cases.cases.size(); ++i) {
    const ProbeCase& c = cases.cases[i];
    std::vector<Value> params;
    for (const auto& p : program->parameters) {
      Value v = p.defaultValue;
      for (const auto& [name, value] : c.parameters)
        if (name == p.name) v = value.convertedTo(p.type);
      params.push_back(v);
    }
    CpuResult ref = evaluateProgram(*program, c.env, params);
    std::array<double, 4> conditioning = conditioningTerm(*program, c.env, params, perturbed, model.roundings);
    report.cases.push_back(compare(c, gpu[i], ref.outputs.front(), c.tolerance.value_or(model.tolerance), conditioning));
  }
  return report;
}

std::string formatProbeText(const ProbeReport& r) {
  std::string out = "probe " + r.graph + " output " + r.output + " (" + std::string(typeName(r.type)) + ") on " +
                    r.target + " (" + r.renderer + "), " + std::to_string(r.cases.size()) +
                    " case" + (r.cases.size() == 1 ? "" : "s") + "\n";
  for (const auto& c : r.cases) {
    out += (c.passed() ? "  ok    " : "  FAIL  ") + c.name + "\n";
    out += "        gpu " + vectorText(c.gpu, c.components) + "\n";
    out += "        ref " + vectorText(c.reference, c.components) + "\n";
    out += "        abs " + fmtShort(c.absError) + "  rel " + fmtShort(c.relError) + "  bound " + fmtShort(c.bound) +
           " (tol " + fmtShort(c.tolerance) + " + cond " + fmtShort(c.conditioning) + ")" +
           "  nan/inf: gpu " + (c.gpuFinite ? "no" : "YES") + ", ref " + (c.referenceFinite ? "no" : "YES") + "\n";
    if (!c.passed()) out += "        why " + c.failure() + "\n";
  }
  out += std::to_string(r.cases.size() - static_cast<size_t>(r.failures())) + "/" + std::to_string(r.cases.size()) +
         " cases passed\n";
  return out;
}

nlohmann::json probeJson(const ProbeReport& r) {
  nlohmann::json j;
  j["graph"] = r.graph;
  j["output"] = r.output;
  j["type"] = std::string(typeName(r.type));
  j["target"] = r.target;
  j["renderer"] = r.renderer;
  j["passed"] = r.passed();
  j["cases"] = nlohmann::json::array();
  for (const auto& c : r.cases) {
    nlohmann::json k;
    k["name"] = c.name;
    if (!c.expect.empty()) k["expect"] = c.expect;
    k["gpu"] = nlohmann::json::array();
    k["reference"] = nlohmann::json::array();
    for (int i = 0; i < c.components; ++i) {
      k["gpu"].push_back(number(c.gpu[static_cast<size_t>(i)]));
      k["reference"].push_back(number(c.reference[static_cast<size_t>(i)]));
    }
    k["abs_error"] = number(c.absError);
    k["rel_error"] = number(c.relError);
    k["tolerance"] = c.tolerance;
    k["conditioning"] = number(c.conditioning);
    k["bound"] = number(c.bound);
    k["gpu_nan_inf"] = !c.gpuFinite;
    k["reference_nan_inf"] = !c.referenceFinite;
    k["passed"] = c.passed();
    if (!c.passed()) k["failure"] = c.failure();
    j["cases"].push_back(k);
  }
  return j;
}

}  // namespace wg::accuracy
