#pragma once
// Derived programs that cover the derived vocabulary (codegen/derived_vocabulary.h), and
// per-draw cases to evaluate them at: what the C header test and the three.js client test
// hold against the double CPU backend. Every node type of the vocabulary appears with vec3
// inputs, with float inputs and (where it has two or more inputs) with a float splatted
// against a vec3; comparisons with every operator; a parameter with a range fed values
// outside it; the per-draw source nodes.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "codegen/derived_c_header.h"
#include "codegen/derived_vocabulary.h"
#include "core/graph_io.h"
#include "core/resolve.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg::test {

struct DerivedSample {
  std::vector<ProgramParameter> parameters;
  std::vector<DerivedUniform> derived;
};

inline DerivedSample derivedVocabularySample() {
  const Registry& registry = defaultRegistry();
  std::string nodes;
  std::vector<std::string> ids;
  auto node = [&](const std::string& id, const std::string& type, const std::vector<std::string>& inputs,
                  const std::string& options = "") {
    const NodeSpec* spec = registry.find(type);
    std::string in;
    for (size_t k = 0; k < inputs.size() && k < spec->inputs.size(); ++k)
      in += (k ? ", " : "") + ("\"" + spec->inputs[k].name + "\": \"" + inputs[k] + "\"");
    nodes += (nodes.empty() ? "" : ",\n") + ("{\"id\": \"" + id + "\", \"type\": \"" + type + "\", \"inputs\": {" + in + "}" +
                                             (options.empty() ? "" : ", \"options\": " + options) + "}");
    ids.push_back(id);
  };
  for (std::string_view tv : derivedNodeTypes()) {
    std::string type(tv);
    const NodeSpec* spec = registry.find(type);
    if (!spec) throw std::logic_error("derived vocabulary type '" + type + "' is no node");
    size_t n = spec->inputs.size();
    if (type == "swizzle") {
      node("swizzle", type, {"$q"});
      node("swizzle_wx", type, {"$q"}, R"({"mask": "wx"})");
      node("swizzle_f", type, {"$f0"}, R"({"mask": "xx"})");
      continue;
    }
    if (type == "split") {
      node("split", type, {"$q"});
      continue;
    }
    if (type == "near_far_ratio") {
      node("near_far_ratio", type, {"$nf"});
      node("near_far_ratio_b", type, {});  // the camera's near/far builtin
      continue;
    }
    std::vector<std::string> vec, flt, mixed;
    for (size_t k = 0; k < n; ++k) {
      const PortSpec& port = spec->inputs[k];
      bool fixedFloat = port.kind == PortKind::Fixed && port.type == Type::Float;
      vec.push_back(fixedFloat ? "$f" + std::to_string(k) : "$v" + std::to_string(k));
      flt.push_back("$f" + std::to_string(k));
      mixed.push_back(k == 0 ? vec[0] : "$f" + std::to_string(k));
    }
    bool fixedVec3 = n > 0 && spec->inputs[0].kind == PortKind::Fixed && spec->inputs[0].type == Type::Vec3;
    if (type == "compare" || type == "select") {
      for (const char* op : {"less", "less_equal", "greater", "greater_equal", "equal", "not_equal"}) {
        node(type + "_" + op, type, vec, std::string("{\"op\": \"") + op + "\"}");
        node(type + "_" + op + "_f", type, flt, std::string("{\"op\": \"") + op + "\"}");
      }
      continue;
    }
    node(type, type, vec);
    if (n > 0 && !fixedVec3 && spec->inputs[0].kind == PortKind::Gen) node(type + "_f", type, flt);
    if (n > 1 && spec->inputs[0].kind == PortKind::Gen && spec->inputs[1].kind == PortKind::Gen) node(type + "_m", type, mixed);
    if (type == "remap") node("remap_clamped", type, vec, R"({"clamp": true})");
  }
  node("srgb_to_linear_q", "srgb_to_linear", {"$q"});  // a vec4: negative, above 1, alpha passed
  node("ranged", "mul", {"$r", "$f1"});  // $r has a range: the clamp is part of the value
  node("time_scaled", "mul", {"time.out", "$v0"});

  std::string params = R"("q": {"type": "vec4", "default": [0.5, -1, 2, 0.25]},
                          "nf": {"type": "vec2", "default": [0.1, 100]},
                          "r": {"type": "float", "default": 0.5, "min": 0, "max": 1})";
  for (int k = 0; k < 5; ++k)
    params += ",\n\"v" + std::to_string(k) + "\": {\"type\": \"vec3\", \"default\": [0.3, -0.7, 1.1]}" + ",\n\"f" +
              std::to_string(k) + "\": {\"type\": \"float\", \"default\": 0.4}";
  // Every node reaches the colour through one sum of their lengths, so none is pruned.
  std::string outputs = R"("fragment": {"color": "uvl.out"})";
  nodes += R"(, {"id": "uv", "type": "uv"}, {"id": "uvl", "type": "length", "inputs": {"x": "uv.out"}})";
  std::string json = graphJson(nodes, outputs, params);

  Diagnostics diags;
  auto graph = parseGraph(json, "derived_sample.json", diags);
  if (!graph) throw std::logic_error("derived sample does not load:\n" + json);
  auto program = resolveGraph(*graph, registry, diags);
  if (!program) {
    std::string why;
    for (const auto& d : diags.sorted()) why += formatText(d) + "\n";
    throw std::logic_error("derived sample does not resolve:\n" + why);
  }
  DerivedSample s;
  s.parameters = program->parameters;
  for (size_t i = 0; i < program->ops.size(); ++i) {
    const Op& op = program->ops[i];
    if (op.nodeId == "uv" || op.nodeId == "uvl") continue;  // the per-pixel colour, not a sample
    for (size_t port = 0; port < op.outputTypes.size(); ++port) {
      if (op.outputTypes[port] == Type::Invalid) continue;
      DerivedUniform u;
      u.uniform = "u_" + op.nodeId + "_" + std::to_string(port);
      u.value = extractDerived(*program, static_cast<int>(i), static_cast<int>(port));
      s.derived.push_back(std::move(u));
    }
  }
  return s;
}

struct DerivedCase {
  std::string what;
  EvalEnvironment env;
  std::vector<Value> parameters;  // by the sample's parameter index
};

// Cases: defaults; zeros (zero vectors, empty ranges, 0^y); equal values (edges, ties);
// negatives; halves; large magnitudes (exp, sinh and mod's guards); a value below a range and NaN.
inline std::vector<DerivedCase> derivedSampleCases(const std::vector<ProgramParameter>& parameters) {
  std::vector<DerivedCase> cases;
  auto make = [&](const std::string& what, auto valueOf) {
    DerivedCase c;
    c.what = what;
    c.env.time = Value::scalar(valueOf(0, 7));
    c.env.cameraPosition = Value::vector({valueOf(1, 0), valueOf(2, 1), valueOf(3, 2)});
    c.env.sunDirection = Value::vector({0.6, 0.8, 0.0});
    // A view matrix: a rotation by angles from the case, scaled (0 in "zeros": degenerate).
    const double yaw = valueOf(1, 5), pitch = valueOf(2, 5), scale = valueOf(3, 5);
    const double cy = std::cos(yaw), sy = std::sin(yaw), cp = std::cos(pitch), sp = std::sin(pitch);
    const double rows[3][3] = {{cy, 0, -sy}, {sy * sp, cp, cy * sp}, {sy * cp, -sp, cy * cp}};
    c.env.view = Value::ofType(Type::Mat4);
    for (int col = 0; col < 3; ++col)
      for (int row = 0; row < 3; ++row) c.env.view[col * 4 + row] = rows[row][col] * scale;
    c.env.view[15] = 1;
    // Near and far as the runtime clamps them (every client clamps the same way).
    auto plane = [](double x) { return !(x >= 1e-6) ? 1e-6 : std::min(x, 1e30); };
    c.env.cameraNearFar = Value::vector({plane(valueOf(0, 3)), plane(100 * valueOf(0, 4))});
    for (size_t i = 0; i < parameters.size(); ++i) {
      Value v = Value::ofType(parameters[i].type);
      for (int k = 0; k < v.size(); ++k) v[k] = valueOf(static_cast<int>(i) + 4, k);
      c.parameters.push_back(v);
    }
    cases.push_back(c);
  };
  make("spread", [](int i, int k) { return std::sin(1.7 * i + 0.9 * k + 0.3) * (1.0 + 0.5 * k); });
  make("zeros", [](int, int) { return 0.0; });
  make("equal", [](int, int) { return 0.75; });
  make("negative", [](int i, int k) { return -0.5 - 0.25 * ((i + k) % 5); });
  make("large", [](int i, int k) { return (i + k) % 2 ? 1e6 + i : -300.0 - k; });
  make("huge time", [](int i, int k) { return i == 0 ? 1e7 + 0.25 : 1.5 + 0.1 * k; });
  // Halves: where round's ties go (2.5 to 2, -1.5 to -2).
  make("halves", [](int i, int k) { return ((i + k) % 2 ? -1.0 : 1.0) * (0.5 + (i + k) % 4); });
  make("nan", [](int i, int k) { return (i + k) % 3 ? std::numeric_limits<double>::quiet_NaN() : 2.0; });
  return cases;
}

// The runtime's clamp of a parameter into its range (runtime/uniform_values.h), in double.
inline Value clampedParameter(const ProgramParameter& p, Value v) {
  double lo = p.min ? *p.min : -std::numeric_limits<double>::infinity();
  double hi = p.max ? *p.max : std::numeric_limits<double>::infinity();
  for (int k = 0; k < v.size(); ++k) {
    double& x = v[k];
    if (!(x >= lo)) x = std::isfinite(lo) ? lo : (std::isfinite(hi) ? hi : x);
    if (x > hi) x = hi;
  }
  return v;
}

}  // namespace wg::test
