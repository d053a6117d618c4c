// Derived uniforms in the plan (issue #19, CompileOptions::derivedUniforms): the fragment
// shader reads u_derived<k> instead of computing the per-draw cone, the manifest carries
// each one's program and reads back to the same bytes, a cone with a node type outside the
// whitelist stays in the shader, and the output is deterministic.
#include <functional>

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

// Every example graph's derived programs read back: the checks below refuse only what the
// compiler never writes.
TEST(DerivedPlan, EveryExampleGraphsDerivedProgramsReadBack) {
  int derived = 0;
  for (const std::string& path : test::exampleGraphs()) {
    SCOPED_TRACE(path);
    Diagnostics diags;
    auto graph = loadGraphFile(path, diags);
    ASSERT_TRUE(graph) << allText(diags);
    CompileOptions options;
    options.targets = {Target::Glsl330};
    options.derivedUniforms = true;
    auto r = compileGraph(*graph, defaultRegistry(), options, diags);
    ASSERT_TRUE(r) << allText(diags);
    for (const auto& u : r->manifest.uniforms) derived += u.derived != nullptr;
    std::string text = r->manifest.fileText();
    EXPECT_EQ(Manifest::fromJson(nlohmann::json::parse(text)).fileText(), text);
  }
  EXPECT_GE(derived, 20) << "the example graphs hold derived uniforms of many node types";
}

// A hand-edited or hostile manifest: each derived program the compiler would not write is a
// ManifestError naming what is wrong, never an exception of another kind at read time nor a
// wrong-sized value at the first draw (before, a `mul` with one input read past its inputs
// when evaluated, and a number where a name goes escaped as nlohmann's type_error).
TEST(DerivedPlan, AProgramTheCompilerWouldNotWriteIsAManifestError) {
  CompileResult r = compileText("@graphs/lagoon.json", true);
  nlohmann::json base = nlohmann::json::parse(r.manifest.fileText());
  size_t at = 0;
  // lagoon's first derived uniform of several ops (before it, its colours' one-op linearisations):
  // time, time * $flow_speed, that * 0.6, combine, fract.
  auto several = [&](size_t k) { return base["uniforms"][k]["derived"]["ops"].size() >= 5; };
  while (at < base["uniforms"].size() && (base["uniforms"][at].value("builtin", "") != "derived" || !several(at))) ++at;
  ASSERT_LT(at, base["uniforms"].size());
  ASSERT_EQ(base["uniforms"][at]["derived"]["ops"][1]["type"], "mul");
  ASSERT_EQ(base["uniforms"][at]["derived"]["ops"][3]["type"], "combine");
  using json = nlohmann::json;
  struct Case {
    const char* what;
    std::function<void(json&)> spoil;
    const char* message;  // in the error
  };
  const Case cases[] = {
      {"an op's node id is a number", [](json& d) { d["ops"][0]["node"] = 5; }, "wrong kind"},
      {"an op's type is a number", [](json& d) { d["ops"][0]["type"] = 5; }, "wrong kind"},
      {"an op is a number", [](json& d) { d["ops"][0] = 5; }, "not an object"},
      {"a mul with one input", [](json& d) { d["ops"][1]["inputs"].erase(1), d["ops"][1]["input_types"].erase(1); },
       "has 1 inputs; its type has 2"},
      {"a combine with one input",
       [](json& d) { d["ops"][3]["inputs"] = json::array({{{"op", 1}, {"port", 0}}}), d["ops"][3]["input_types"] = {"float"}; },
       "has 1 inputs; its type has 4"},
      {"input types the inputs do not give", [](json& d) { d["ops"][1]["input_types"] = {"vec4", "vec4"}; }, "port types"},
      {"three output types", [](json& d) { d["ops"][1]["output_types"] = {"float", "float", "float"}; }, "port types"},
      {"a constant of a string", [](json& d) { d["ops"][2]["inputs"][1]["constant"] = {"x"}; }, "wrong kind"},
      {"a constant of null", [](json& d) { d["ops"][2]["inputs"][1]["constant"] = {nullptr}; }, "wrong kind"},
      {"an op index as text", [](json& d) { d["ops"][1]["inputs"][0]["op"] = "0"; }, "wrong kind"},
      {"a builtin as a number", [](json& d) { d["ops"][1]["inputs"][1] = {{"builtin", 4}}; }, "wrong kind"},
      {"the value a number", [](json& d) { d["value"] = 3; }, "needs \"ops\" and \"value\""},
      {"options a number", [](json& d) { d["ops"][3]["options"] = 7; }, "not an object"},
      {"an option value not in its list", [](json& d) { d["ops"][3]["options"] = {{"type", "mat9"}}; }, "'mat9'"},
      {"an option the type does not have", [](json& d) { d["ops"][3]["options"] = {{"size", 2}}; }, "no option 'size'"},
      {"a value type its op does not give", [](json& d) { d["type"] = "vec3"; }, "op output is not of its type"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    json m = base;
    c.spoil(m["uniforms"][at]["derived"]);
    try {
      Manifest::fromJson(m);
      ADD_FAILURE() << "accepted";
    } catch (const ManifestError& e) {
      EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << "not a ManifestError: " << e.what();
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
