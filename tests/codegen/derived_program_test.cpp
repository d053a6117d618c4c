// Derived values (codegen/derived_program.h): a per-draw cone taken out of a Program
// evaluates to what the whole Program computes there, and survives its manifest form.
#include <gtest/gtest.h>

#include "codegen/compile.h"
#include "codegen/cpu_backend.h"
#include "codegen/derived_program.h"
#include "codegen/frequency_report.h"
#include "pass_test_support.h"

namespace wg {
namespace derived_program_test {

using namespace passtest;


// dir = normalize($wind) * (k * 2 + time); shade reads it with the uv.
const std::string kGraph = graphJson(
    R"({"id": "u", "type": "uv"}, {"id": "l", "type": "length", "inputs": {"x": "u.out"}},
       {"id": "t", "type": "time"},
       {"id": "k2", "type": "mul", "inputs": {"a": "$k", "b": 2}},
       {"id": "kt", "type": "add", "inputs": {"a": "k2.out", "b": "t.out"}},
       {"id": "w", "type": "normalize", "inputs": {"x": "$wind"}},
       {"id": "dir", "type": "mul", "inputs": {"a": "w.out", "b": "kt.out"}},
       {"id": "shade", "type": "mul", "inputs": {"a": "dir.out", "b": "l.out"}})",
    R"("fragment": {"color": "shade.out"})",
    R"("k": {"type": "float", "default": 0.5}, "wind": {"type": "vec3", "default": [1, 0, 2]})");

TEST(DerivedProgram, TheExtractedConeComputesWhatTheProgramDoes) {
  Program p = finalProgram(kGraph);
  FrequencyReport r = frequencyReport(p);
  ASSERT_EQ(r.candidates.size(), 1u) << formatFrequencyReport(p, r);
  int root = r.candidates[0].op;
  EXPECT_EQ(root, opIndex(p, "dir"));
  DerivedValue d = extractDerived(p, root, 0);
  EXPECT_EQ(d.program.ops.size(), 5u) << "t, k2, kt, w, dir";
  EXPECT_EQ(d.type, Type::Vec3);
  EvalEnvironment env;
  env.time = Value::scalar(1234.5);
  std::vector<Value> params = {Value::scalar(0.25), Value::vector({0, 3, 4})};
  CpuResult whole = evaluateProgram(p, env, params);
  Value want = whole.opOutputs[static_cast<size_t>(root)][0];
  Value got = evaluateDerived(d, env, params);
  EXPECT_EQ(got, want);
  EXPECT_DOUBLE_EQ(got[1], 0.6 * 1235.0);

  // The manifest form reads back to the same value.
  std::string error;
  auto back = derivedFromJson(nlohmann::json::parse(derivedToJson(d).dump()), defaultRegistry(), p.parameters, error);
  ASSERT_TRUE(back) << error;
  EXPECT_EQ(evaluateDerived(*back, env, params), want);
  EXPECT_EQ(derivedToJson(*back), derivedToJson(d));
}

TEST(DerivedProgram, APerPixelValueIsRefused) {
  Program p = finalProgram(kGraph);
  EXPECT_THROW(extractDerived(p, opIndex(p, "shade"), 0), std::logic_error);
}

TEST(DerivedProgram, TheManifestFormRefusesWhatItCannotEvaluate) {
  Program p = finalProgram(kGraph);
  nlohmann::json j = derivedToJson(extractDerived(p, opIndex(p, "dir"), 0));
  size_t k2 = 0;
  while (k2 < j["ops"].size() && j["ops"][k2]["node"] != "k2") ++k2;
  ASSERT_LT(k2, j["ops"].size());
  std::string error;
  nlohmann::json noParam = j;
  noParam["ops"][k2]["inputs"][0] = {{"parameter", "nope"}};
  EXPECT_FALSE(derivedFromJson(noParam, defaultRegistry(), p.parameters, error));
  EXPECT_NE(error.find("nope"), std::string::npos) << error;
  nlohmann::json perPixel = j;
  perPixel["ops"][k2]["inputs"][0] = {{"builtin", "uv"}};
  EXPECT_FALSE(derivedFromJson(perPixel, defaultRegistry(), p.parameters, error));
  nlohmann::json forward = j;
  forward["ops"][0]["inputs"] = nlohmann::json::array({{{"op", 3}, {"port", 0}}});
  forward["ops"][0]["input_types"] = nlohmann::json::array({"float"});
  EXPECT_FALSE(derivedFromJson(forward, defaultRegistry(), p.parameters, error));
}

}  // namespace derived_program_test
}  // namespace wg
