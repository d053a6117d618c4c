// Derived uniforms in the plan (issue #19, CompileOptions::derivedUniforms): the fragment
// shader reads u_derived<k> instead of computing the per-draw cone, the manifest carries
// each one's program and reads back to the same bytes, a cone with a node type outside the
// whitelist stays in the shader, and the output is deterministic.
#include <gtest/gtest.h>

#include "codegen/compile.h"
#include "codegen/derived_program.h"
#include "codegen/derived_vocabulary.h"
#include "codegen/manifest.h"
#include "core/graph_io.h"
#include "pass_test_support.h"
#include "test_support.h"

namespace wg {
namespace derived_plan_test {

using namespace passtest;

// dir = normalize($wind) * sin(time * $k): per draw; shade multiplies it per pixel by |uv|.
std::string graphWith(const std::string& wave) {
  return graphJson(
      R"({"id": "u", "type": "uv"}, {"id": "l", "type": "length", "inputs": {"x": "u.out"}},
         {"id": "t", "type": "time"},
         {"id": "kt", "type": "mul", "inputs": {"a": "t.out", "b": "$k"}},
         {"id": "s", "type": ")" + wave + R"(", "inputs": {"x": "kt.out"}},
         {"id": "w", "type": "normalize", "inputs": {"x": "$wind"}},
         {"id": "dir", "type": "mul", "inputs": {"a": "w.out", "b": "s.out"}},
         {"id": "shade", "type": "mul", "inputs": {"a": "dir.out", "b": "l.out"}})",
      R"("fragment": {"color": "shade.out"})",
      R"("k": {"type": "float", "default": 0.5, "min": 0, "max": 4},
         "wind": {"type": "vec3", "default": [1, 0, 2]})");
}

// `json` is graph text, or "@" and a path under the source tree (an example graph).
CompileResult compileText(const std::string& json, bool derive, std::vector<Target> targets = {Target::Glsl330}) {
  Diagnostics diags;
  auto graph = json.rfind('@', 0) == 0 ? loadGraphFile(test::sourcePath(json.substr(1)), diags)
                                        : parseGraph(json, "test.json", diags);
  EXPECT_TRUE(graph) << allText(diags);
  if (!graph) return {};
  CompileOptions options;
  options.targets = std::move(targets);
  options.derivedUniforms = derive;
  auto r = compileGraph(*graph, defaultRegistry(), options, diags);
  EXPECT_TRUE(r) << allText(diags);
  return r ? std::move(*r) : CompileResult{};
}

const std::string& fileOf(const CompileResult& r, const std::string& name) {
  for (const auto& f : r.files)
    if (f.name == name) return f.contents;
  static const std::string none;
  ADD_FAILURE() << "no file " << name;
  return none;
}

const ManifestUniform* uniformNamed(const Manifest& m, const std::string& name) {
  for (const auto& u : m.uniforms)
    if (u.name == name) return &u;
  return nullptr;
}

TEST(DerivedPlan, TheFragmentShaderReadsTheUniformInsteadOfTheCone) {
  CompileResult off = compileText(graphWith("sin"), false);
  CompileResult on = compileText(graphWith("sin"), true);
  const std::string& fragOff = fileOf(off, "test.glsl330.frag");
  const std::string& fragOn = fileOf(on, "test.glsl330.frag");
  EXPECT_NE(fragOff.find("sin("), std::string::npos) << fragOff;
  EXPECT_EQ(fragOff.find("u_derived"), std::string::npos) << fragOff;
  EXPECT_NE(fragOn.find("uniform vec3 u_derived0;"), std::string::npos) << fragOn;
  // The cone is gone: no sine, no normalisation, no parameter it read.
  EXPECT_EQ(fragOn.find("sin("), std::string::npos) << fragOn;
  EXPECT_EQ(fragOn.find("normalize"), std::string::npos) << fragOn;
  EXPECT_EQ(fragOn.find("p_wind"), std::string::npos) << fragOn;
  EXPECT_EQ(fragOn.find("u_time"), std::string::npos) << fragOn;
  // The parameters stay in the manifest (the runtime needs their values and ranges),
  // declared in no stage.
  const ManifestUniform* wind = uniformNamed(on.manifest, "p_wind");
  ASSERT_NE(wind, nullptr);
  EXPECT_EQ(wind->stages, 0u);
  const ManifestUniform* d = uniformNamed(on.manifest, "u_derived0");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->builtin, BuiltinUniform::Derived);
  EXPECT_EQ(d->type, Type::Vec3);
  EXPECT_EQ(d->stages, kFragmentStage);
  ASSERT_TRUE(d->derived);
  // Its program is the cone: time, time * k, sin, normalize, the product.
  EXPECT_EQ(d->derived->program.ops.size(), 5u);
  // Nothing else became one: the per-pixel ops stay.
  EXPECT_EQ(uniformNamed(on.manifest, "u_derived1"), nullptr);
}

TEST(DerivedPlan, ANodeTypeOutsideTheWhitelistKeepsTheConeInTheShader) {
  EXPECT_FALSE(isDerivedNodeType("reflect"));
  std::string graph = graphWith("sin");
  const std::string sine = R"("type": "sin", "inputs": {"x": "kt.out"})";
  ASSERT_NE(graph.find(sine), std::string::npos);
  graph.replace(graph.find(sine), sine.size(), R"("type": "reflect", "inputs": {"incident": "kt.out", "normal": "kt.out"})");
  CompileResult on = compileText(graph, true);
  const std::string& frag = fileOf(on, "test.glsl330.frag");
  EXPECT_EQ(frag.find("u_derived"), std::string::npos) << frag;
  EXPECT_NE(frag.find("reflect("), std::string::npos) << frag;  // the cone, computed per pixel
}

TEST(DerivedPlan, TheWhitelistIsSortedAndEveryTypeIsANode) {
  const auto& types = derivedNodeTypes();
  for (size_t i = 0; i < types.size(); ++i) {
    EXPECT_NE(defaultRegistry().find(std::string(types[i])), nullptr) << types[i];
    if (i) {
      EXPECT_LT(types[i - 1], types[i]);
    }
  }
}

// The manifest's derived programs read back, byte for byte and value for value; lagoon
// (the example graph with candidates) compiles and validates on every target with it.
TEST(DerivedPlan, TheManifestRoundTripsTheDerivedPrograms) {
  for (const std::string& json : {graphWith("sin"), std::string("@graphs/lagoon.json")}) {
    CompileResult r = compileText(json, true, {Target::Glsl330, Target::Es300, Target::Vk450});
    std::string text = r.manifest.fileText();
    ASSERT_NE(text.find("\"builtin\": \"derived\""), std::string::npos);
    Manifest back = Manifest::fromJson(nlohmann::json::parse(text));
    EXPECT_EQ(back.fileText(), text);
    const auto parameters = manifestParameters(back.uniforms);
    std::vector<Value> values;
    for (const auto& p : parameters) values.push_back(p.defaultValue);
    EvalEnvironment env;
    env.time = Value::scalar(7.25);
    env.cameraPosition = Value::vector({1, 2, 3});
    int derived = 0;
    for (size_t i = 0; i < back.uniforms.size(); ++i) {
      if (back.uniforms[i].builtin != BuiltinUniform::Derived || back.uniforms[i].parameter) continue;
      ++derived;
      ASSERT_TRUE(back.uniforms[i].derived);
      ASSERT_TRUE(r.manifest.uniforms[i].derived);
      EXPECT_EQ(evaluateDerived(*back.uniforms[i].derived, env, values),
                evaluateDerived(*r.manifest.uniforms[i].derived, env, values));
    }
    EXPECT_GE(derived, 1);
    // A derived uniform without its program, or one of another type, is refused.
    nlohmann::json j = nlohmann::json::parse(text);
    for (auto& u : j["uniforms"])
      if (u.value("builtin", "") == "derived") {
        nlohmann::json bad = j;
        for (auto& v : bad["uniforms"])
          if (v["name"] == u["name"]) v.erase("derived");
        EXPECT_THROW(Manifest::fromJson(bad), ManifestError);
        bad = j;
        for (auto& v : bad["uniforms"])
          if (v["name"] == u["name"]) v["type"] = v["type"] == "float" ? "vec4" : "float";
        EXPECT_THROW(Manifest::fromJson(bad), ManifestError);
        break;
      }
  }
}

TEST(DerivedPlan, TheOutputIsDeterministicAndOffChangesNothing) {
  const std::string lagoon = "@graphs/lagoon.json";
  CompileResult a = compileText(lagoon, true, {Target::Glsl330, Target::Vk450});
  CompileResult b = compileText(lagoon, true, {Target::Glsl330, Target::Vk450});
  ASSERT_EQ(a.files.size(), b.files.size());
  for (size_t i = 0; i < a.files.size(); ++i) EXPECT_EQ(a.files[i].contents, b.files[i].contents) << a.files[i].name;
  CompileResult off = compileText(lagoon, false, {Target::Glsl330});
  EXPECT_EQ(fileOf(off, "lagoon.glsl330.frag").find("u_derived"), std::string::npos);
  EXPECT_NE(fileOf(a, "lagoon.glsl330.frag").find("u_derived0"), std::string::npos);
}

}  // namespace derived_plan_test
}  // namespace wg
