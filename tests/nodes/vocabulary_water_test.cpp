// Two water formulas built from math vocabulary nodes only, against the built-in nodes
// that hard-code them, in double: Beer-Lambert absorption, T = exp(-sigma d) (absorption,
// model beer_lambert), and Schlick's Fresnel, F = f0 + (1 - f0)(1 - saturate(N.V))^5
// (fresnel, model schlick, from above). Within 1e-12, so the vocabulary is enough to write
// them by hand.
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "codegen/cpu_backend.h"
#include "core/graph_io.h"
#include "core/resolve.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg {
namespace {

std::string vec3(double x, double y, double z) {
  return "[" + std::to_string(x) + ", " + std::to_string(y) + ", " + std::to_string(z) + "]";
}

// Every op's outputs of a resolved graph (no passes: nothing folds), by node id.
struct Evaluated {
  Program program;
  CpuResult result;
  const Value& at(const std::string& node, int port = 0) const {
    for (size_t i = 0; i < program.ops.size(); ++i)
      if (program.ops[i].nodeId == node) return result.opOutputs[i][static_cast<size_t>(port)];
    throw std::out_of_range("no op " + node);
  }
};

Evaluated evaluate(const std::string& nodes, const std::string& outputs, const EvalEnvironment& env = {}) {
  Diagnostics diags;
  auto graph = parseGraph(test::graphJson(nodes, outputs), "vocabulary.json", diags);
  std::string why;
  for (const auto& d : diags.all()) why += formatText(d) + "\n";
  if (!graph) throw std::runtime_error(why);
  auto program = resolveGraph(*graph, defaultRegistry(), diags);
  for (const auto& d : diags.all()) why += formatText(d) + "\n";
  if (!program) throw std::runtime_error(why);
  Evaluated e{std::move(*program), {}};
  e.result = evaluateProgram(e.program, env);
  return e;
}

TEST(VocabularyWater, BeerLambertFromExpNegateAndMulMatchesAbsorption) {
  const double pureWater[3] = {0.340, 0.0565, 0.00922}, murky[3] = {0, 1, 3.5};
  for (double d : {0.0, 0.5, 10.0, 250.0})
    for (const double* sg : {pureWater, murky}) {
      std::string sigma = vec3(sg[0], sg[1], sg[2]);
      SCOPED_TRACE("d = " + std::to_string(d) + ", sigma = " + sigma);
      std::string nodes = R"({"id": "path", "type": "mul", "inputs": {"a": )" + sigma + R"(, "b": )" + std::to_string(d) + R"(}},
        {"id": "optical_depth", "type": "negate", "inputs": {"x": "path.out"}},
        {"id": "by_hand", "type": "exp", "inputs": {"x": "optical_depth.out"}},
        {"id": "builtin", "type": "absorption", "inputs": {"distance": )" + std::to_string(d) + R"(, "sigma": )" + sigma + "}}";
      Evaluated e = evaluate(nodes, R"("fragment": {"color": "by_hand.out"})");
      const Value &mine = e.at("by_hand"), &theirs = e.at("builtin", 0);
      ASSERT_EQ(mine.size(), 3);
      for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(mine[i], theirs[i], 1e-12) << "channel " << i;
        EXPECT_NEAR(mine[i], std::exp(-sg[i] * d), 1e-12) << "channel " << i << " against Beer-Lambert itself";
      }
    }
}

TEST(VocabularyWater, SchlickFromDotSaturateOneMinusPowMixMatchesFresnel) {
  for (double degrees : {0.0, 30.0, 60.0, 85.0, 90.0, 100.0})
    for (double f0 : {0.02, 0.04, 0.5}) {
      SCOPED_TRACE(std::to_string(degrees) + " deg, f0 " + std::to_string(f0));
      double r = degrees * 3.14159265358979323846 / 180;
      EvalEnvironment env;
      env.normal = Value::vector({0, 1, 0});
      env.viewDirection = Value::vector({std::sin(r), std::cos(r), 0});
      std::string nodes = R"({"id": "n", "type": "normal"}, {"id": "v", "type": "view_direction"},
        {"id": "cosine", "type": "dot", "inputs": {"a": "n.out", "b": "v.out"}},
        {"id": "c", "type": "saturate", "inputs": {"x": "cosine.out"}},
        {"id": "m", "type": "one_minus", "inputs": {"x": "c.out"}},
        {"id": "m5", "type": "pow", "inputs": {"x": "m.out", "y": 5}},
        {"id": "by_hand", "type": "mix", "inputs": {"a": )" + std::to_string(f0) + R"(, "b": 1, "t": "m5.out"}},
        {"id": "builtin", "type": "fresnel", "options": {"model": "schlick"}, "inputs": {"f0": )" + std::to_string(f0) + "}}";
      Evaluated e = evaluate(nodes, R"("fragment": {"alpha": "by_hand.out"})", env);
      double mine = e.at("by_hand")[0], theirs = e.at("builtin", 0)[0];
      EXPECT_NEAR(mine, theirs, 1e-12);
      // An oracle of its own, so the two cannot agree on a wrong value.
      double c = std::max(0.0, std::cos(r));
      EXPECT_NEAR(mine, f0 + (1 - f0) * std::pow(1 - c, 5), 1e-12);
    }
}

}  // namespace
}  // namespace wg
