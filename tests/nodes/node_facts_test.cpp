// Every node's declared value facts (NodeSpec::facts) hold on its double reference: the
// compiler drops guards on their word (codegen/value_facts.h), so a fact that is wrong
// for some input is a NaN or a wrong value in the shader. Each node with facts is
// evaluated at its hard cases and at seeded random inputs; every input is given a random
// fact that contains its value (a constant, an interval, or a unit vector marked
// normalized), and each output must lie within the facts the node declares for them.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "codegen/cpu_backend.h"
#include "core/node_options.h"
#include "nodes/registry.h"
#include "nodes/texture_source.h"
#include "test_support.h"

namespace wg {
namespace {

struct Sample {
  std::vector<std::pair<std::string, Value>> inputs;
  std::vector<ValueFact> facts;  // one per input port of the spec
};

// A port's type for a random value: Gen ports as float (the narrowest they take).
Type sampleType(const PortSpec& p) { return p.kind == PortKind::Fixed ? p.type : Type::Float; }

// A value for `p` and a fact that holds for it: components from a wide, a unit and a tiny
// scale, zero now and then; a vec3 is made unit (and said to be) half of the time.
void randomInput(const PortSpec& p, std::mt19937& rng, Sample& out) {
  Type t = sampleType(p);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> pick(0, 5);
  std::vector<double> c(static_cast<size_t>(componentCount(t)));
  const double scale[] = {1, 10, 1e3, 1e-3, 1, 0.5};
  int s = pick(rng);
  for (double& x : c) x = pick(rng) == 0 ? 0.0 : unit(rng) * scale[s];
  ValueFact f;
  bool makeUnit = t == Type::Vec3 && pick(rng) < 3;
  if (makeUnit) {
    double len = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    if (len == 0) c = {0, 1, 0}, len = 1;
    for (double& x : c) x /= len;
    f = ValueFact::unitVector();
  } else {
    double lo = c[0], hi = c[0];
    for (double x : c) lo = std::min(lo, x), hi = std::max(hi, x);
    switch (pick(rng) % 3) {
      case 0: f = {lo, hi, false}; break;                                   // exact (a constant)
      case 1: f = {lo - std::abs(unit(rng)), hi + std::abs(unit(rng)), false}; break;  // an interval
      default: break;                                                      // nothing known
    }
  }
  Value v = Value::ofType(t);
  for (size_t i = 0; i < c.size(); ++i) v[static_cast<int>(i)] = c[i];
  out.inputs.emplace_back(p.name, v);
  out.facts.push_back(f);
}

// The sea an ocean reader's `ocean` input takes: an ocean_spectrum of 64^2 with two
// cascades (quick to simulate), evaluated once.
Value smallSea() {
  static const Value sea = [] {
    TextureCache textures;
    nlohmann::json options = {{"fft_size", 64}, {"tile_lengths", {50, 8}}};
    return evaluateNode(*defaultRegistry().find("ocean_spectrum"), options, {}, EvalEnvironment{}, &textures,
                        test::sourceDir())[0];
  }();
  return sea;
}

// Whether `v` satisfies `f`, within rounding of the double reference. `normalized` is unit
// length, or shorter than 1 where a safe normalisation met a vector shorter than 1e-15
// (ValueFact): `tinyInput` says an input was such a vector.
std::string violation(const Value& v, const ValueFact& f, bool tinyInput) {
  double len2 = 0;
  for (int i = 0; i < v.size(); ++i) {
    if (!(v[i] >= f.lo - 1e-9 * std::max(1.0, std::abs(f.lo)))) return "component below the fact's lower bound";
    if (!(v[i] <= f.hi + 1e-9 * std::max(1.0, std::abs(f.hi)))) return "component above the fact's upper bound";
    len2 += v[i] * v[i];
  }
  double len = std::sqrt(len2);
  if (f.normalized && v.size() > 1 && len > 1 + 1e-6) return "longer than 1";
  if (f.normalized && v.size() > 1 && len2 != 0 && !tinyInput && std::abs(len - 1) > 1e-6) return "not a unit vector";
  return "";
}

TEST(NodeFacts, DeclaredFactsHoldOnTheReference) {
  std::mt19937 rng(20261128);
  int nodes = 0, checked = 0;
  for (const NodeSpec* s : defaultRegistry().all()) {
    if (!s->facts) continue;
    bool simple = true;  // fixed or Gen inputs only: Custom ports take their types from a graph
    for (const PortSpec& p : s->inputs) simple = simple && (p.kind != PortKind::Custom || p.derived);
    if (!simple) continue;
    ++nodes;
    std::vector<Sample> samples;
    for (int i = 0; i < 200; ++i) {
      Sample smp;
      for (const PortSpec& p : s->inputs) {
        if (p.derived) {
          smp.facts.push_back({});
          continue;
        }
        if (p.kind == PortKind::Fixed && p.type == Type::Ocean) {  // a sea, not a value to draw
          smp.inputs.emplace_back(p.name, smallSea());
          smp.facts.push_back({});
          continue;
        }
        randomInput(p, rng, smp);
      }
      samples.push_back(std::move(smp));
    }
    for (const HardCase& hc : s->hardCases) {  // at their own options: the facts know nothing of the inputs
      if (!hc.options.empty()) continue;
      Sample smp;
      smp.inputs.assign(hc.inputs.begin(), hc.inputs.end());
      for (const PortSpec& p : s->inputs)
        if (p.kind == PortKind::Fixed && p.type == Type::Ocean) {  // the case's own sea
          TextureCache textures;
          smp.inputs.emplace_back(p.name, evaluateNode(*defaultRegistry().find("ocean_spectrum"), hc.oceanOptions, {},
                                                       EvalEnvironment{}, &textures, test::sourceDir())[0]);
        }
      smp.facts.assign(s->inputs.size(), ValueFact{});
      samples.push_back(std::move(smp));
    }
    std::shared_ptr<const ParsedOptions> options = parseOptions(*s, completeOptions(*s, nlohmann::json::object()));
    for (const Sample& smp : samples) {
      TextureCache textures;
      std::vector<Value> outs;
      try {
        outs = evaluateNode(*s, nlohmann::json::object(), smp.inputs, EvalEnvironment{}, &textures, test::sourceDir());
      } catch (const std::invalid_argument& e) {
        ADD_FAILURE() << s->type << ": " << e.what();
        break;
      }
      std::vector<ValueFact> declared = s->facts(smp.facts, *options);
      bool tinyInput = false;
      for (const auto& [name, v] : smp.inputs) {
        double l2 = 0;
        for (int c = 0; c < v.size(); ++c) l2 += v[c] * v[c];
        tinyInput |= v.size() > 1 && l2 > 0 && l2 < 1e-28;
      }
      for (size_t o = 0; o < outs.size() && o < declared.size(); ++o) {
        if (outs[o].type == Type::Invalid) continue;
        std::string why = violation(outs[o], declared[o], tinyInput);
        ++checked;
        if (why.empty()) continue;
        std::string in;
        for (const auto& [name, v] : smp.inputs) in += " " + name + "=" + v.toString();
        ADD_FAILURE() << s->type << "." << s->outputs[o].name << " = " << outs[o].toString() << ": " << why
                      << " [" << declared[o].lo << ", " << declared[o].hi << "]" << (declared[o].normalized ? " unit" : "")
                      << "; inputs" << in;
        break;
      }
    }
  }
  // Reaches what it names: most nodes with facts, each output many times.
  EXPECT_GE(nodes, 20);
  EXPECT_GE(checked, 20 * 200);
}

}  // namespace
}  // namespace wg
