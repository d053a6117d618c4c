// The three.js client's evaluator of derived uniforms (clients/three/watergraph-derived.js),
// run under node on the manifest form of programs covering the whole derived vocabulary,
// computes what the runtime's double CPU backend computes, at the same edge values as the
// C header's test (zeros, ties, NaN, huge arguments). It refuses what it cannot compute.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "codegen/cpu_backend.h"
#include "derived_samples.h"
#include "eco_support.h"

namespace wg::eco {
namespace {

std::string evaluator() { return test::sourcePath("clients/three/test/derived_eval.mjs"); }

nlohmann::json valueJson(const Value& v) {
  if (v.size() == 1) return v[0];  // nlohmann writes NaN as null, which the script reads back
  nlohmann::json a = nlohmann::json::array();
  for (int i = 0; i < v.size(); ++i) a.push_back(v[i]);
  return a;
}

bool sameFloat(double got, double want) {
  if (std::isnan(want)) return std::isnan(got);
  float w = static_cast<float>(want), g = static_cast<float>(got);
  // One float ulp: JavaScript's Math functions and the C library may round a transcendental
  // differently in the last double bit, which moves the uploaded float only at a boundary.
  return g == w || g == std::nextafter(w, INFINITY) || g == std::nextafter(w, -INFINITY);
}

TEST(DerivedJs, ComputesWhatTheCpuBackendComputes) {
  test::DerivedSample s = test::derivedVocabularySample();
  std::vector<test::DerivedCase> cases = test::derivedSampleCases(s.parameters);
  nlohmann::json in = {{"programs", nlohmann::json::array()}, {"cases", nlohmann::json::array()}};
  for (const auto& u : s.derived) in["programs"].push_back(derivedToJson(u.value));
  for (const auto& c : cases) {
    nlohmann::json params = nlohmann::json::object();
    for (size_t i = 0; i < s.parameters.size(); ++i)
      params[s.parameters[i].name] = valueJson(test::clampedParameter(s.parameters[i], c.parameters[i]));
    in["cases"].push_back({{"parameters", params},
                           {"draw",
                            {{"time", c.env.time[0]},
                             {"camera_position", valueJson(c.env.cameraPosition)},
                             {"near", c.env.cameraNearFar[0]},
                             {"far", c.env.cameraNearFar[1]},
                             {"sun_direction", valueJson(c.env.sunDirection)}}}});
  }
  TempDir dir("wg_derived_js_");
  const std::string file = dir / "programs.json";
  std::ofstream(file) << in.dump();
  CmdResult r = sh("timeout 60 node " + test::shellQuote(evaluator()) + " " + test::shellQuote(file));
  ASSERT_EQ(r.exit, 0) << r.err;
  nlohmann::json out = nlohmann::json::parse(r.out);
  ASSERT_EQ(out["results"].size(), cases.size());
  size_t compared = 0;
  for (size_t k = 0; k < cases.size(); ++k) {
    std::vector<Value> params;
    for (size_t i = 0; i < s.parameters.size(); ++i) params.push_back(test::clampedParameter(s.parameters[i], cases[k].parameters[i]));
    for (size_t u = 0; u < s.derived.size(); ++u) {
      Value want = evaluateDerived(s.derived[u].value, cases[k].env, params);
      const nlohmann::json& got = out["results"][k][u];
      ASSERT_EQ(got.size(), static_cast<size_t>(want.size())) << s.derived[u].uniform;
      for (int j = 0; j < want.size(); ++j, ++compared) {
        const nlohmann::json& x = got[static_cast<size_t>(j)];
        double g = x.is_number() ? x.get<double>() : x == "inf" ? INFINITY : x == "-inf" ? -INFINITY : NAN;
        EXPECT_TRUE(sameFloat(g, want[j])) << "case " << cases[k].what << ", " << s.derived[u].uniform << "[" << j
                                           << "]: JS " << g << ", backend " << want[j];
      }
    }
  }
  EXPECT_GT(compared, 500u);
}

TEST(DerivedJs, RefusesANodeTypeOutsideTheVocabulary) {
  nlohmann::json program = {{"type", "float"},
                            {"value", {{"op", 0}, {"port", 0}}},
                            {"ops", {{{"node", "n"}, {"type", "voronoi"}, {"options", nlohmann::json::object()},
                                      {"inputs", nlohmann::json::array()}, {"input_types", nlohmann::json::array()},
                                      {"output_types", {"float"}}}}}};
  nlohmann::json in = {{"programs", {program}}, {"cases", nlohmann::json::array()}};
  TempDir dir("wg_derived_js_");
  const std::string file = dir / "programs.json";
  std::ofstream(file) << in.dump();
  CmdResult r = sh("timeout 60 node " + test::shellQuote(evaluator()) + " " + test::shellQuote(file));
  EXPECT_NE(r.exit, 0);
  EXPECT_NE(r.err.find("node type 'voronoi' cannot be computed outside the shader"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace wg::eco
