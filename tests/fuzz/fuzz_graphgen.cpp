// libFuzzer target: graphs generated from the fuzz bytes, so that most inputs are valid
// enough to reach the passes, the emitters and glslang (mutated JSON rarely gets past the
// resolver). The bytes choose node types from the registry, option values (choices, range
// ends, defaults, wave lists), and wire each input to an earlier node's output of a fitting
// type, a literal, or a parameter; then the graph is written as JSON and checked with
// pipelineProperty (fuzz_properties.h): a clear error, or GLSL glslang accepts everywhere.
// A failing input's graph is printed, to save as tests/fuzz/regressions/graphgen_*.json.
#include <fuzzer/FuzzedDataProvider.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/expression_types.h"
#include "core/node_options.h"
#include "fuzz_properties.h"

namespace {

using nlohmann::json;
using wg::NodeSpec;
using wg::OptionSpec;
using wg::PortKind;
using wg::Type;

struct Out {
  std::string ref;  // "n3.normal"
  PortKind kind;
  Type type;
};

json literalOf(FuzzedDataProvider& fdp, int width) {
  static const double kValues[] = {0.0, 1.0, -1.0, 0.5, 2.0, 1e-7, 1e7, -3.4e38, 3.4e38, 1e-38, 0.25, 100.0};
  auto one = [&] {
    return fdp.ConsumeBool() ? kValues[fdp.ConsumeIntegralInRange<size_t>(0, std::size(kValues) - 1)]
                             : fdp.ConsumeFloatingPointInRange<double>(-1e4, 1e4);
  };
  if (width == 1) return one();
  json a = json::array();
  for (int i = 0; i < width; ++i) a.push_back(one());
  return a;
}

int widthOf(Type t) {
  switch (t) {
    case Type::Vec2: return 2;
    case Type::Vec3: return 3;
    case Type::Vec4: return 4;
    default: return 1;
  }
}

// A formula for an `expression` node over its inputs a and b: every construct of the
// language (literals, names, operators, calls of the vocabulary, constructors, swizzles,
// ?:), nested a few levels, so most are well-formed and many are well-typed.
std::string formula(FuzzedDataProvider& fdp, int depth) {
  static const char* kNames[] = {"a", "b", "1.0", "0.0", "-2.5", "1e30", "3.0e-7"};
  if (depth <= 0 || fdp.remaining_bytes() == 0)
    return kNames[fdp.ConsumeIntegralInRange<size_t>(0, std::size(kNames) - 1)];
  switch (fdp.ConsumeIntegralInRange(0, 6)) {
    case 0: return "-" + formula(fdp, depth - 1);
    case 1: {
      static const char* kOps[] = {" + ", " - ", " * ", " / "};
      return "(" + formula(fdp, depth - 1) + kOps[fdp.ConsumeIntegralInRange(0, 3)] + formula(fdp, depth - 1) + ")";
    }
    case 2: {
      const auto& fns = wg::expr::formulaFunctions();
      const auto& f = fns[fdp.ConsumeIntegralInRange<size_t>(0, fns.size() - 1)];
      std::string call = std::string(f.name) + "(";
      for (int i = 0; i < f.arity; ++i) call += (i ? ", " : "") + formula(fdp, depth - 1);
      return call + ")";
    }
    case 3: {
      int n = fdp.ConsumeIntegralInRange(2, 4);
      std::string call = "vec" + std::to_string(n) + "(";
      int args = fdp.ConsumeIntegralInRange(1, n);
      for (int i = 0; i < args; ++i) call += (i ? ", " : "") + formula(fdp, depth - 1);
      return call + ")";
    }
    case 4: {
      static const char* kMasks[] = {"x", "xy", "zyx", "rgba", "s", "wwww"};
      return formula(fdp, depth - 1) + "." + kMasks[fdp.ConsumeIntegralInRange<size_t>(0, std::size(kMasks) - 1)];
    }
    case 5: {
      static const char* kCmp[] = {" < ", " <= ", " > ", " >= ", " == ", " != "};
      return "(" + formula(fdp, depth - 1) + kCmp[fdp.ConsumeIntegralInRange(0, 5)] + formula(fdp, depth - 1) + " ? " +
             formula(fdp, depth - 1) + " : " + formula(fdp, depth - 1) + ")";
    }
    default: return kNames[fdp.ConsumeIntegralInRange<size_t>(0, 1)];
  }
}

json optionValue(FuzzedDataProvider& fdp, const OptionSpec& o) {
  if (fdp.ConsumeIntegralInRange(0, 3) == 0) return o.defaultValue;
  switch (o.kind) {
    case OptionSpec::Kind::Enum:
      if (o.choices.empty()) return o.defaultValue;
      return o.choices[fdp.ConsumeIntegralInRange<size_t>(0, o.choices.size() - 1)];
    case OptionSpec::Kind::Number:
    case OptionSpec::Kind::Integer: {
      double lo = o.min.value_or(-1e6), hi = o.max.value_or(1e6);
      double x;
      switch (fdp.ConsumeIntegralInRange(0, 2)) {
        case 0: x = lo; break;
        case 1: x = hi; break;
        default: x = fdp.ConsumeFloatingPointInRange<double>(lo, hi);
      }
      if (o.kind == OptionSpec::Kind::Integer) return static_cast<long long>(x);
      return x;
    }
    case OptionSpec::Kind::Bool: return fdp.ConsumeBool();
    case OptionSpec::Kind::Texture: {
      static const char* kTex[] = {"builtin:foam", "builtin:dudv", "builtin:height", "builtin:water_normal"};
      return kTex[fdp.ConsumeIntegralInRange<size_t>(0, std::size(kTex) - 1)];
    }
    case OptionSpec::Kind::Text:
      return formula(fdp, fdp.ConsumeIntegralInRange(0, 4));
    case OptionSpec::Kind::Json:
      if (o.name == "inputs") {  // an expression's declared inputs: a and b, of any type
        static const char* kTypes[] = {"float", "vec2", "vec3", "vec4"};
        return json{{"a", kTypes[fdp.ConsumeIntegralInRange(0, 3)]}, {"b", kTypes[fdp.ConsumeIntegralInRange(0, 3)]}};
      }
      if (o.name == "mask") {
        std::string m;
        int n = fdp.ConsumeIntegralInRange(1, 4);
        for (int i = 0; i < n; ++i) m += "xyzwrgba"[fdp.ConsumeIntegralInRange(0, 7)];
        return m;
      }
      if (o.name == "waves") {
        json waves = json::array();
        int n = fdp.ConsumeIntegralInRange(1, 16);
        for (int i = 0; i < n; ++i) {
          json w = {{"direction", {fdp.ConsumeFloatingPointInRange<double>(-1, 1), fdp.ConsumeFloatingPointInRange<double>(-1, 1)}},
                    {"steepness", fdp.ConsumeFloatingPointInRange<double>(0, 1.0 / n)},
                    {"wavelength", fdp.ConsumeBool() ? fdp.ConsumeFloatingPointInRange<double>(1e-3, 1e3) : 1e-30}};
          if (fdp.ConsumeBool()) w["phase"] = fdp.ConsumeFloatingPointInRange<double>(-1e6, 1e6);
          if (fdp.ConsumeBool()) w["amplitude"] = fdp.ConsumeFloatingPointInRange<double>(0, 10);
          waves.push_back(w);
        }
        return waves;
      }
      return o.defaultValue;
  }
  return o.defaultValue;
}

std::string generate(FuzzedDataProvider& fdp) {
  const auto& specs = wg::defaultRegistry().all();
  json g = {{"version", 1}, {"name", "gen"}, {"nodes", json::array()}, {"outputs", json::object()}};
  // Parameters of each type; some static (folded by specialise).
  const char* pTypes[] = {"float", "vec2", "vec3", "vec4"};
  std::vector<Out> outs;
  for (int i = 0; i < 4; ++i) {
    json p = {{"type", pTypes[i]}, {"default", literalOf(fdp, i + 1)}};
    if (fdp.ConsumeBool()) p["static"] = true;
    g["parameters"]["p" + std::to_string(i)] = p;
  }
  int nodes = fdp.ConsumeIntegralInRange(1, 16);
  for (int i = 0; i < nodes && fdp.remaining_bytes() > 0; ++i) {
    const NodeSpec* spec = specs[fdp.ConsumeIntegralInRange<size_t>(0, specs.size() - 1)];
    std::string id = "n" + std::to_string(i);
    json node = {{"id", id}, {"type", spec->type}};
    for (const auto& o : spec->options)
      if (fdp.ConsumeBool()) node["options"][o.name] = optionValue(fdp, o);
    // An expression's ports are those its options declare.
    for (const auto& port : wg::portsOfNode(*spec, node.contains("options") ? node["options"] : json::object()).inputs) {
      int how = fdp.ConsumeIntegralInRange(0, 9);
      if (!port.required() && how < 3) continue;  // default
      // An earlier output that fits: same fixed type, or any for Gen/Custom ports.
      std::vector<const Out*> fit;
      for (const auto& o : outs)
        if (port.kind != PortKind::Fixed || (o.kind == PortKind::Fixed && o.type == port.type) || o.kind != PortKind::Fixed)
          fit.push_back(&o);
      int width = port.kind == PortKind::Fixed ? widthOf(port.type) : fdp.ConsumeIntegralInRange(1, 4);
      if (how < 7 && !fit.empty())
        node["inputs"][port.name] = fit[fdp.ConsumeIntegralInRange<size_t>(0, fit.size() - 1)]->ref;
      else if (how == 7)
        node["inputs"][port.name] = "$p" + std::to_string(width - 1);
      else
        node["inputs"][port.name] = literalOf(fdp, width);
    }
    for (const auto& o : spec->outputs) outs.push_back({id + "." + o.name, o.kind, o.type});  // expression: out, Custom
    g["nodes"].push_back(node);
  }
  // Outputs: color and alpha (and sometimes the vertex slots) from the last nodes.
  auto pick = [&]() -> json {
    if (outs.empty() || fdp.ConsumeIntegralInRange(0, 5) == 0) return literalOf(fdp, 3);
    size_t lo = outs.size() > 6 ? outs.size() - 6 : 0;
    return outs[fdp.ConsumeIntegralInRange<size_t>(lo, outs.size() - 1)].ref;
  };
  g["outputs"]["fragment"]["color"] = pick();
  if (fdp.ConsumeBool()) g["outputs"]["fragment"]["alpha"] = pick();
  if (fdp.ConsumeBool()) g["outputs"]["vertex"]["position"] = pick();
  if (fdp.ConsumeBool()) g["outputs"]["vertex"]["normal"] = pick();
  return g.dump(2);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  std::atexit(wg::fuzz::printPipelineStats);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzedDataProvider fdp(data, size);
  std::string text = generate(fdp);
  std::string failed = wg::fuzz::pipelineProperty(text);
  if (!failed.empty()) {
    std::fprintf(stderr, "watergraph pipeline property failed for the generated graph:\n%s\n%s\n", text.c_str(),
                 failed.c_str());
    std::abort();
  }
  return 0;
}
