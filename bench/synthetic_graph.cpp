#include "bench/synthetic_graph.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <vector>

namespace wg::bench {
namespace {

// A number as JSON text, short and exact enough for a benchmark constant.
std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", x);
  return buf;
}

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

class Writer {
 public:
  explicit Writer(int limit) : limit_(limit) { text_.reserve(static_cast<size_t>(limit) * 110 + 4096); }

  bool full() const { return count_ >= limit_; }
  int count() const { return count_; }

  // Adds a node unless the limit is reached; `inputs` and `options` are JSON object bodies.
  bool node(const std::string& id, const std::string& type, const std::string& inputs = "",
            const std::string& options = "") {
    if (full()) return false;
    text_ += count_ ? ",\n    " : "\n    ";
    text_ += "{\"id\": " + quoted(id) + ", \"type\": " + quoted(type);
    if (!options.empty()) text_ += ", \"options\": {" + options + "}";
    if (!inputs.empty()) text_ += ", \"inputs\": {" + inputs + "}";
    text_ += "}";
    ++count_;
    return true;
  }

  std::string& text() { return text_; }

 private:
  int limit_;
  int count_ = 0;
  std::string text_;
};

std::string in(const std::string& port, const std::string& source) { return quoted(port) + ": " + source; }
std::string ref(const std::string& node, const std::string& port) { return quoted(node + "." + port); }

}  // namespace

std::string syntheticGraphJson(int nodes) {
  nodes = std::max(nodes, 10);
  // Parameters grow slowly with the graph (real graphs have tens, not thousands), so the
  // uniform count stays within every target's limits.
  const int params = std::clamp(nodes / 200, 1, 16);
  std::string text = "{\n  \"version\": 1,\n  \"name\": \"synthetic_" + std::to_string(nodes) +
                     "\",\n  \"description\": \"generated for the compile benchmarks\",\n  \"parameters\": {";
  for (int j = 0; j < params; ++j) {
    text += (j ? ",\n    " : "\n    ") + quoted("gain" + std::to_string(j)) +
            ": {\"type\": \"float\", \"default\": " + num(1 + 0.01 * j) + ", \"min\": 0, \"max\": 4}";
    text += ",\n    " + quoted("depth" + std::to_string(j)) + ": {\"type\": \"float\", \"default\": " + num(4 + j) +
            ", \"min\": 0.1, \"max\": 50}";
  }
  text += ",\n    \"tint\": {\"type\": \"vec3\", \"default\": [0, 0.4, 0.6], \"hint\": \"color\"}";
  text += ",\n    \"slope\": {\"type\": \"float\", \"default\": 0.25, \"static\": true}";
  text += ",\n    \"unused\": {\"type\": \"float\", \"default\": 1}";
  text += "\n  },\n  \"nodes\": [";

  Writer w(nodes);
  // Header: the inputs every water graph reads, and a displaced vertex stage.
  w.node("uv", "uv");
  w.node("pos", "world_position");
  w.node("nrm", "normal");
  w.node("waves", "gerstner_waves", "",
         "\"waves\": [{\"direction\": [1, 0.3], \"steepness\": 0.4, \"wavelength\": 8}, "
         "{\"direction\": [-0.2, 1], \"steepness\": 0.2, \"wavelength\": 3}]");
  w.node("surface", "vertex_output", in("position", ref("waves", "position")) + ", " + in("normal", ref("waves", "normal")));
  w.node("clock", "time");

  std::vector<std::string> floats = {ref("clock", "out")};
  std::vector<std::string> vec3s = {ref("pos", "out"), ref("nrm", "out"), "\"$tint\""};
  std::string f = floats[0], c = vec3s[0];  // the block's inputs: the previous block's results
  std::string alpha = f, color = c;         // the latest float and vec3 made, for the outputs
  uint32_t lcg = 12345;
  auto pick = [&lcg](const std::vector<std::string>& from) {
    lcg = lcg * 1664525u + 1013904223u;
    return from[(lcg >> 8) % from.size()];
  };

  for (int i = 0; !w.full(); ++i) {
    const std::string b = "b" + std::to_string(i) + "_";
    const double k = 0.5 + (i % 997) * 0.003;
    const std::string gain = "\"$gain" + std::to_string(i % params) + "\"";
    const std::string depth = "\"$depth" + std::to_string(i % params) + "\"";
    const std::string skipF = pick(floats), skipC = pick(vec3s);

    if (!w.node(b + "scale", "mul", in("a", f) + ", " + in("b", i % 7 == 0 ? gain : num(k)))) break;
    alpha = ref(b + "scale", "out");
    if (!w.node(b + "wave", "sin", in("x", ref(b + "scale", "out")))) break;
    alpha = ref(b + "wave", "out");
    std::string water;
    switch (i % 6) {
      case 0:
        w.node(b + "fresnel", "fresnel", in("f0", num(0.02 + 0.0001 * (i % 50))), "\"model\": \"schlick\"");
        water = ref(b + "fresnel", "reflectance");
        break;
      case 1:
        w.node(b + "cells", "voronoi", in("p", ref("uv", "out")) + ", " + in("scale", num(4 + k)));
        water = ref(b + "cells", "f1");
        break;
      case 2:
        w.node(b + "noise", "value_noise", in("p", ref("uv", "out")) + ", " + in("scale", num(8 * k)));
        water = ref(b + "noise", "value");
        break;
      case 3:
        w.node(b + "tint", "depth_tint", in("depth", ref(b + "wave", "out")) + ", " + in("max_depth", depth));
        water = ref(b + "tint", "factor");
        break;
      case 4:
        w.node(b + "edge", "smoothstep", in("edge0", "0") + ", " + in("edge1", num(k)) + ", " + in("x", skipF));
        water = ref(b + "edge", "out");
        break;
      default:
        w.node(b + "fbm", "fbm", in("p", ref("uv", "out")) + ", " + in("scale", num(3 * k)), "\"octaves\": 3");
        water = ref(b + "fbm", "value");
        break;
    }
    if (w.full()) break;
    if (!w.node(b + "sum", "add", in("a", ref(b + "wave", "out")) + ", " + in("b", water))) break;
    alpha = ref(b + "sum", "out");
    if (!w.node(b + "mix", "mix", in("a", c) + ", " + in("b", skipC) + ", " + in("t", ref(b + "sum", "out")))) break;
    color = ref(b + "mix", "out");
    if (!w.node(b + "lit", "dot", in("a", ref(b + "mix", "out")) + ", " + in("b", ref("nrm", "out")))) break;
    alpha = ref(b + "lit", "out");
    // Even blocks repeat the sine (CSE merges it), odd ones clamp the lighting.
    std::string sixth = i % 2 == 0 ? b + "again" : b + "clamp";
    bool ok = i % 2 == 0 ? w.node(sixth, "sin", in("x", ref(b + "scale", "out")))
                         : w.node(sixth, "clamp", in("x", ref(b + "lit", "out")) + ", " + in("lo", "0") + ", " + in("hi", "1"));
    if (!ok) break;
    if (!w.node(b + "out", "mul", in("a", ref(b + "lit", "out")) + ", " + in("b", ref(sixth, "out")))) break;
    alpha = ref(b + "out", "out");
    // One block in ten leaves a debug node nobody reads (prune); one in ten multiplies two
    // constants (fold) or a static parameter (specialise); the rest normalise the colour.
    std::string base = ref(b + "mix", "out"), offset = ref(b + "out", "out");
    if (i % 10 == 9) {
      if (!w.node(b + "debug", "sub", in("a", ref(b + "out", "out")) + ", " + in("b", "1"))) break;
    } else if (i % 10 == 4) {
      if (!w.node(b + "const", "mul", in("a", num(k)) + ", " + in("b", i % 20 == 4 ? "\"$slope\"" : "2"))) break;
      offset = ref(b + "const", "out");
    } else {
      if (!w.node(b + "norm", "normalize", in("x", ref(b + "mix", "out")))) break;
      base = ref(b + "norm", "out");
    }
    if (!w.node(b + "col", "add", in("a", base) + ", " + in("b", offset))) break;
    color = ref(b + "col", "out");
    f = ref(b + "out", "out");
    c = color;
    floats.push_back(ref(b + "sum", "out"));
    floats.push_back(f);
    vec3s.push_back(ref(b + "mix", "out"));
    vec3s.push_back(c);
  }
  text += w.text();
  text += "\n  ],\n  \"outputs\": {\n    \"vertex\": {\"position\": " + ref("surface", "position") +
          ", \"normal\": " + ref("surface", "normal") + "},\n    \"fragment\": {\"color\": " + color +
          ", \"alpha\": " + alpha + "}\n  }\n}\n";
  return text;
}

}  // namespace wg::bench
