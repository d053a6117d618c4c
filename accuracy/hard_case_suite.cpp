#include "accuracy/hard_case_suite.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <stdexcept>

#include "accuracy/gpu_executor.h"
#include "accuracy/node_probe.h"
#include "accuracy/number_text.h"
#include "codegen/emit_glsl.h"
#include "core/node_options.h"
#include "nodes/registry.h"
#include "runtime/runtime_error.h"

namespace wg::accuracy {
namespace {

// The options of each variant: the defaults, then one option changed at a time.
std::vector<std::pair<std::string, nlohmann::json>> optionVariants(const NodeSpec& spec, bool all) {
  std::vector<std::pair<std::string, nlohmann::json>> out = {{"defaults", nlohmann::json::object()}};
  if (!all) return out;
  for (const auto& o : spec.options) {
    std::vector<nlohmann::json> values;
    if (o.kind == OptionSpec::Kind::Enum)
      for (const auto& c : o.choices) values.push_back(c);
    else if (o.kind == OptionSpec::Kind::Bool)
      values = {true, false};
    else if (o.kind == OptionSpec::Kind::Integer && o.min && o.max)
      values = {static_cast<int>(*o.min), static_cast<int>(*o.max)};
    for (const auto& v : values) {
      if (v == o.defaultValue) continue;
      out.push_back({o.name + "=" + (v.is_string() ? v.get<std::string>() : v.dump()), nlohmann::json{{o.name, v}}});
    }
  }
  return out;
}

// The node's own documented hard cases as suite cases (default environment).
std::vector<ProbeCase> specHardCases(const NodeSpec& spec) {
  std::vector<ProbeCase> out;
  for (const auto& hc : spec.hardCases) {
    ProbeCase c;
    c.name = "own:" + hc.name;
    c.expect = hc.expectation;
    c.env = defaultProbeEnvironment();
    for (const auto& [port, value] : hc.inputs) c.inputs.emplace_back(port, toFloat32(value));
    c.options = nlohmann::json{{spec.type, hc.options}};
    if (!hc.oceanOptions.empty()) c.options[spec.type][kOceanOptionsKey] = hc.oceanOptions;
    std::string output = hc.output.empty() ? spec.outputs.front().name : hc.output;
    c.ranges[spec.type + "." + output] = {hc.lo, hc.hi};
    c.tolerance = hc.tolerance;
    out.push_back(std::move(c));
  }
  return out;
}

// Whether case `c` gives an input of the node in its default options (an expression's
// inputs are those its default options declare).
bool takesInput(const NodeSpec& spec, const ProbeCase& c) {
  NodePorts ports = portsOfNode(spec, nlohmann::json::object());
  for (const auto& [port, value] : c.inputs)
    for (const auto& p : ports.inputs)
      if (p.name == port) return true;
  return false;
}

}  // namespace

std::vector<std::string> nodeReads(const NodeSpec& spec) {
  NodeProbeSetup setup = makeNodeProbe(spec, nlohmann::json::object(), {});
  Diagnostics diags;
  std::set<std::string> keys;
  for (const auto& out : spec.outputs) {
    auto program = buildProbeProgram(setup.graph, defaultRegistry(), ProbeOutput{"n", out.name}, diags);
    if (!program) continue;
    EmitResult shader = emitProgram(*program, Target::Glsl330, setup.graph.file, EmitMode::Probe);
    auto insert = [&](const CaseKeys& k) {
      for (std::string_view key : k)
        if (!key.empty()) keys.emplace(key);
    };
    for (const auto& u : shader.uniforms)
      if (u.parameter < 0) insert(builtinUniformRow(u.builtin).caseKeys);
    for (const auto& t : shader.textures)
      if (t.scene) insert(sceneResourceRow(sceneSamplerRow(*t.scene).resource).caseKeys);
    // The ocean maps are simulated at the case's time.
    if (!shader.oceans.empty()) keys.emplace("time");
  }
  return {keys.begin(), keys.end()};
}

SuiteResult runHardCaseSuite(const ProbeCaseFile& suite, Target target, const SuiteOptions& options) {
  return runHardCaseSuite(suite, *currentGlExecutor(target), options);
}

SuiteResult runHardCaseSuite(const ProbeCaseFile& suite, GpuExecutor& executor, const SuiteOptions& options) {
  const std::string target = executor.targetLabel();
  SuiteResult result;
  for (const NodeSpec* spec : defaultRegistry().all()) {
    if (!options.nodes.empty() && std::find(options.nodes.begin(), options.nodes.end(), spec->type) == options.nodes.end())
      continue;
    std::vector<std::string> reads = nodeReads(*spec);
    std::vector<ProbeCase> applicable;
    for (const auto& c : suite.cases) {
      if (!c.nodes.empty() && std::find(c.nodes.begin(), c.nodes.end(), spec->type) == c.nodes.end()) continue;
      bool applies = takesInput(*spec, c);
      for (const auto& key : reads) applies |= c.given.count(key) > 0;
      if (applies) applicable.push_back(c);
    }
    for (const auto& [variant, variantOptions] : optionVariants(*spec, options.variants)) {
      std::vector<ProbeCase> cases = applicable;
      if (variant == "defaults" && options.nodeHardCases)
        for (auto& c : specHardCases(*spec)) cases.push_back(std::move(c));
      // Cases that bring options for this node type run in groups of equal options.
      std::map<std::string, std::pair<nlohmann::json, std::vector<ProbeCase>>> groups;
      for (const auto& c : cases) {
        nlohmann::json o = variantOptions;
        if (c.options.contains(spec->type))
          for (auto it = c.options[spec->type].begin(); it != c.options[spec->type].end(); ++it) o[it.key()] = it.value();
        auto& g = groups[o.dump()];
        g.first = o;
        g.second.push_back(c);
      }
      for (const auto& [key, group] : groups) {
        for (const auto& out : spec->outputs) {
          Diagnostics diags;
          std::optional<ProbeReport> report;
          std::string label = spec->type + " [" + variant + (key == variantOptions.dump() ? "" : ", " + key) + "]." + out.name;
          try {
            report = probeNode(*spec, group.first, out.name, group.second, executor, diags, options.mutation);
          } catch (const rt::RuntimeError& e) {
            result.errors.push_back(label + ": " + e.what());
            continue;
          } catch (const std::invalid_argument&) {
            if (!options.mutation.active()) throw;
            continue;  // the mutated text is not in this run's shader
          }
          if (report && !report->cases.empty() && options.mutation.active()) ++result.mutatedRuns;
          if (!report) {
            // Not applicable: split's 'w' of a vec3, a float given where swizzle needs a vector.
            bool absent = true;
            for (const auto& d : diags.all()) absent &= d.code == DiagCode::UnknownOutputPort || d.code == DiagCode::TypeMismatch;
            if (absent && !diags.all().empty()) continue;
            std::string why;
            for (const auto& d : diags.all()) why += " " + formatText(d);
            result.errors.push_back(label + ":" + why);
            continue;
          }
          for (const auto& c : report->cases) {
            ++result.caseRuns;
            if (c.passed()) continue;
            ++result.failures;
            if (!c.gpuFinite || !c.referenceFinite) ++result.nanInf;
            std::string gpu, ref;
            for (int i = 0; i < c.components; ++i) {
              gpu += (i ? ", " : "") + significantDigits(c.gpu[static_cast<size_t>(i)], 6);
              ref += (i ? ", " : "") + significantDigits(c.reference[static_cast<size_t>(i)], 6);
            }
            result.failureLines.push_back(target + " " + label + " case '" + c.name +
                                          "': " + c.failure() + " (gpu " + gpu + "; ref " + ref + ")");
          }
          result.runs.push_back({spec->type, variant, completeOptions(*spec, group.first), std::move(*report)});
        }
      }
    }
  }
  return result;
}

}  // namespace wg::accuracy
