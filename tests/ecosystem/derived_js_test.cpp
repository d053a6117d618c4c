// The three.js client's evaluator of derived uniforms (clients/three/watergraph-derived.js),
// run under node on the manifest form of programs covering the whole derived vocabulary,
// computes what the runtime's double CPU backend computes, at the same edge values as the
// C header's test (zeros, ties, NaN, huge arguments). It refuses what it cannot compute.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>

#include <nlohmann/json.hpp>

#include "codegen/cpu_backend.h"
#include "codegen/manifest.h"
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
                             {"sun_direction", valueJson(c.env.sunDirection)},
                             {"view", valueJson(c.env.view)}}}});
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

// A hostile manifest: an input or the value naming an output port the op does not have is
// refused when the program is compiled, not a TypeError at the first draw.
TEST(DerivedJs, RefusesAProgramTheCompilerWouldNotWrite) {
  auto timeOp = [] {
    return nlohmann::json{{"node", "t"}, {"type", "time"}, {"options", nlohmann::json::object()},
                          {"inputs", nlohmann::json::array()}, {"input_types", nlohmann::json::array()},
                          {"output_types", {"float"}}};
  };
  nlohmann::json badInput = {{"type", "float"}, {"value", {{"op", 1}, {"port", 0}}},
                             {"ops", {timeOp(), {{"node", "s"}, {"type", "sin"}, {"options", nlohmann::json::object()},
                                                 {"inputs", {{{"op", 0}, {"port", 3}}}}, {"input_types", {"float"}},
                                                 {"output_types", {"float"}}}}}};
  nlohmann::json badValue = {{"type", "float"}, {"value", {{"op", 0}, {"port", 1}}}, {"ops", {timeOp()}}};
  // A mul with one input (it would read past its inputs at the first draw), and a constant
  // that is not an array.
  nlohmann::json oneInput = {{"type", "float"}, {"value", {{"op", 1}, {"port", 0}}},
                             {"ops", {timeOp(), {{"node", "m"}, {"type", "mul"}, {"options", nlohmann::json::object()},
                                                 {"inputs", {{{"op", 0}, {"port", 0}}}}, {"input_types", {"float"}},
                                                 {"output_types", {"float"}}}}}};
  nlohmann::json scalarConstant = oneInput;
  scalarConstant["ops"][1]["inputs"] = {{{"op", 0}, {"port", 0}}, {{"constant", 2}, {"type", "float"}}};
  scalarConstant["ops"][1]["input_types"] = {"float", "float"};
  for (const auto& [program, message] : {std::pair{badInput, std::string("reads no output of op 0")},
                                         std::pair{badValue, std::string("the value is no op output")},
                                         std::pair{oneInput, std::string("1 inputs; a 'mul' has 2")},
                                         std::pair{scalarConstant, std::string("a constant that is not an array")}}) {
    TempDir dir("wg_derived_js_");
    const std::string file = dir / "programs.json";
    std::ofstream(file) << nlohmann::json{{"programs", {program}}, {"cases", nlohmann::json::array()}}.dump();
    CmdResult r = sh("timeout 60 node " + test::shellQuote(evaluator()) + " " + test::shellQuote(file));
    EXPECT_NE(r.exit, 0);
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
  }
}

// The client wired to a compiled graph (clients/three/test/derived_client.mjs): after
// update(time, camera) and after setParameter of every parameter a derived program reads (to
// a value past its range, which the client clamps), each derived uniform holds what the
// runtime's evaluator computes from the same frame and parameters, and changes with them.
TEST(DerivedJs, TheClientSetsDerivedUniformsAsTheRuntime) {
  TempDir dir("wg_derived_client_");
  CmdResult c = wgRun("compile " + test::shellQuote(test::sourcePath("graphs/lagoon.json")) + " -o " +
                      test::shellQuote(dir.path()) + " --target es300 --derived-uniforms --quiet");
  ASSERT_EQ(c.exit, 0) << c.err;
  Manifest manifest = Manifest::fromJson(nlohmann::json::parse(test::readFile(dir / "lagoon.manifest.json")));
  const std::vector<ProgramParameter> parameters = manifestParameters(manifest.uniforms);
  std::vector<const ManifestUniform*> derived;
  std::set<std::string> read;  // the parameters the derived programs read
  for (const auto& u : manifest.uniforms)
    if (u.derived) {
      derived.push_back(&u);
      for (const Op& op : u.derived->program.ops)
        for (const ValueRef& r : op.inputs)
          if (r.kind == ValueRef::Kind::Param) read.insert(parameters[static_cast<size_t>(r.index)].name);
    }
  ASSERT_FALSE(derived.empty());
  ASSERT_FALSE(read.empty());
  std::string sets;
  for (const auto& p : parameters) {
    if (!read.count(p.name)) continue;
    nlohmann::json v = nlohmann::json::array();
    for (int k = 0; k < p.defaultValue.size(); ++k) v.push_back(p.max ? *p.max + 5 : p.defaultValue[k] + 1);
    sets += " " + test::shellQuote(p.name + "=" + (p.defaultValue.size() == 1 ? v[0].dump() : v.dump()));
  }
  CmdResult r = sh("cd " + test::shellQuote(test::sourcePath("clients/three")) + " && timeout 60 node test/derived_client.mjs " +
                   test::shellQuote(dir.path()) + " lagoon" + sets);
  ASSERT_EQ(r.exit, 0) << r.err;
  nlohmann::json out = nlohmann::json::parse(r.out);
  ASSERT_EQ(out["steps"].size(), 1 + read.size());
  auto valueOf = [](const nlohmann::json& a) {
    std::vector<double> v = a.get<std::vector<double>>();
    Value r = Value::ofType(v.size() == 16 ? Type::Mat4 : floatVector(static_cast<int>(v.size())));
    for (int i = 0; i < r.size(); ++i) r[i] = v[static_cast<size_t>(i)];
    return r;
  };
  std::vector<std::vector<double>> first;
  for (size_t s = 0; s < out["steps"].size(); ++s) {
    const nlohmann::json& step = out["steps"][s];
    const nlohmann::json& f = step["frame"];
    EvalEnvironment env;
    env.time = Value::scalar(f["time"].get<double>());
    env.cameraPosition = valueOf(f["camera_position"]);
    auto plane = [](double x) { return !(x >= 1e-6) ? 1e-6 : std::min(x, 1e30); };
    env.cameraNearFar = Value::vector({plane(f["near"].get<double>()), plane(f["far"].get<double>())});
    env.view = valueOf(f["view"]);
    env.projection = valueOf(f["projection"]);
    env.sunDirection = valueOf(f["sun_direction"]);
    std::vector<Value> params;
    size_t setSoFar = 0;  // step s has set the first s parameters read (one more per step)
    for (const auto& p : parameters) {
      Value v = valueOf(step["parameters"][p.name]);
      if (read.count(p.name) && ++setSoFar <= s && p.max) {
        EXPECT_EQ(v[0], *p.max) << p.name << ": the client clamps";
      }
      params.push_back(v);
    }
    for (const ManifestUniform* u : derived) {
      Value want = evaluateDerived(*u->derived, env, params);
      std::vector<double> got = step["values"][u->name].get<std::vector<double>>();
      ASSERT_EQ(got.size(), static_cast<size_t>(want.size())) << u->name;
      for (int j = 0; j < want.size(); ++j)
        EXPECT_TRUE(sameFloat(got[static_cast<size_t>(j)], want[j]))
            << "step " << s << ", " << u->name << "[" << j << "]: client " << got[static_cast<size_t>(j)] << ", runtime " << want[j];
      if (s == 0) first.push_back(got);
    }
  }
  bool changed = false;  // setting the parameters moved some derived value
  const nlohmann::json& last = out["steps"].back()["values"];
  for (size_t k = 0; k < derived.size(); ++k) changed = changed || last[derived[k]->name].get<std::vector<double>>() != first[k];
  EXPECT_TRUE(changed);
}

}  // namespace
}  // namespace wg::eco
