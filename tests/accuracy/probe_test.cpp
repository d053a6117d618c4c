// watergraph probe: the cases file (errors at file:line:col), the probe on every example
// graph on both targets, and a probe that must fail (a division by zero gives Inf on the
// GPU and in the reference, and the report says so).
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "accuracy/node_probe.h"
#include "accuracy/probe.h"
#include "core/diagnostic_text.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "runtime/egl_context.h"
#include "test_support.h"

namespace wg::accuracy {
namespace {


TEST(ProbeCases, UnknownKeyIsReportedAtItsPosition) {
  Diagnostics diags;
  auto r = parseProbeCases("{\"cases\": [\n  {\"name\": \"a\",\n   \"tme\": 3}\n]}\n", "c.json", diags);
  EXPECT_FALSE(r);
  EXPECT_NE(core_test::dump(diags).find("c.json:3:4: error: [WG060] unknown key 'tme'"), std::string::npos) << core_test::dump(diags);
}

TEST(ProbeCases, WrongSizeAndDuplicateNameAreErrors) {
  Diagnostics diags;
  auto r = parseProbeCases(R"({"cases": [{"name": "a", "normal": [0, 1]}, {"name": "a"}]})", "c.json", diags);
  EXPECT_FALSE(r);
  std::string m = core_test::dump(diags);
  EXPECT_NE(m.find("c.json:1:36: error: [WG060] \"normal\" must be an array of 3 numbers"), std::string::npos) << m;
  EXPECT_NE(m.find("a second case named 'a'"), std::string::npos) << m;
}

TEST(ProbeCases, InfinityCameraAndDerivedViewDirection) {
  Diagnostics diags;
  auto r = parseProbeCases(R"({"cases": [{"name": "a", "camera": {"position": [0, 3, 4], "far": "inf"}}]})", "c.json", diags);
  ASSERT_TRUE(r) << core_test::dump(diags);
  const EvalEnvironment& env = r->cases[0].env;
  EXPECT_TRUE(std::isinf(env.cameraNearFar[1]));
  EXPECT_FLOAT_EQ(static_cast<float>(env.viewDirection[1]), 0.6f);
  EXPECT_FLOAT_EQ(static_cast<float>(env.viewDirection[2]), 0.8f);
  EXPECT_EQ(env.projection[10], -1.0);  // the infinite-far limit
  EXPECT_TRUE(r->cases[0].given.count("camera"));
}

TEST(ProbeCases, InvalidJsonIsWg001) {
  Diagnostics diags;
  EXPECT_FALSE(parseProbeCases("{\"cases\": [", "c.json", diags));
  EXPECT_NE(core_test::dump(diags).find("[WG001]"), std::string::npos) << core_test::dump(diags);
}

class ProbeOnGpu : public ::testing::TestWithParam<Target> {
 protected:
  void SetUp() override {
    context_ = rt::EglContext::create(GetParam() == Target::Es300 ? rt::GlApi::Es32 : rt::GlApi::DesktopGl45);
  }
  std::unique_ptr<rt::EglContext> context_;
};

TEST_P(ProbeOnGpu, EveryExampleGraphPassesTheGraphCases) {
  Diagnostics diags;
  auto cases = loadProbeCases(test::sourcePath("tests/hardcases/graphs.json"), diags);
  ASSERT_TRUE(cases) << core_test::dump(diags);
  for (const auto& path : test::exampleGraphs()) {
    SCOPED_TRACE(path);
    auto graph = loadGraphFile(path, diags);
    ASSERT_TRUE(graph) << core_test::dump(diags);
    auto report = probeGraph(*graph, {}, *cases, GetParam(), diags);
    ASSERT_TRUE(report) << core_test::dump(diags);
    EXPECT_EQ(report->cases.size(), cases->cases.size());
    EXPECT_TRUE(report->passed()) << formatProbeText(*report);
  }
}

TEST_P(ProbeOnGpu, DivisionByZeroIsFlaggedAsInfinite) {
  Diagnostics diags;
  auto graph = parseGraph(R"({"version": 1, "name": "d", "parameters": {"b": {"type": "float", "default": 1}},
    "nodes": [{"id": "q", "type": "div", "inputs": {"a": 1, "b": "$b"}}],
    "outputs": {"fragment": {"alpha": "q.out"}}})", "d.json", diags);
  ASSERT_TRUE(graph) << core_test::dump(diags);
  auto cases = parseProbeCases(R"({"cases": [{"name": "one", "parameters": {"b": 4}}, {"name": "zero", "parameters": {"b": 0}}]})",
                               "c.json", diags);
  ASSERT_TRUE(cases) << core_test::dump(diags);
  auto report = probeGraph(*graph, ProbeOutput{"q", "out"}, *cases, GetParam(), diags);
  ASSERT_TRUE(report) << core_test::dump(diags);
  ASSERT_EQ(report->cases.size(), 2u);
  EXPECT_TRUE(report->cases[0].passed()) << formatProbeText(*report);
  EXPECT_DOUBLE_EQ(report->cases[0].gpu[0], 0.25);
  EXPECT_FALSE(report->cases[1].gpuFinite);
  EXPECT_FALSE(report->passed());
  EXPECT_EQ(report->cases[1].failure(), "GPU NaN/Inf");
}

TEST_P(ProbeOnGpu, UnknownParameterInACaseIsAnError) {
  Diagnostics diags;
  auto graph = loadGraphFile(test::sourcePath("graphs/lake.json"), diags);
  auto cases = parseProbeCases(R"({"cases": [{"name": "x", "parameters": {"shalow": 1}}]})", "c.json", diags);
  ASSERT_TRUE(graph && cases) << core_test::dump(diags);
  EXPECT_FALSE(probeGraph(*graph, {}, *cases, GetParam(), diags));
  EXPECT_NE(core_test::dump(diags).find("c.json:1:12: error: [WG060] case 'x' sets parameter 'shalow'"), std::string::npos)
      << core_test::dump(diags);
}

TEST_P(ProbeOnGpu, AStaticParameterCannotBeSetByACase) {
  Diagnostics diags;
  auto graph = loadGraphFile(test::sourcePath("graphs/shelf.json"), diags);
  auto cases = parseProbeCases(R"({"cases": [{"name": "s", "parameters": {"slope": 0.5}}]})", "c.json", diags);
  ASSERT_TRUE(graph && cases) << core_test::dump(diags);
  EXPECT_FALSE(probeGraph(*graph, {}, *cases, GetParam(), diags));
  EXPECT_NE(core_test::dump(diags).find("which is static"), std::string::npos) << core_test::dump(diags);
}

TEST_P(ProbeOnGpu, ANodeOutputCanBeProbedAndUnknownPortsAreNamed) {
  Diagnostics diags;
  auto graph = loadGraphFile(test::sourcePath("graphs/lake.json"), diags);
  ASSERT_TRUE(graph);
  std::string node = graph->nodes.back().id;
  ProbeCaseFile cases;
  cases.cases.push_back(ProbeCase{});
  cases.cases[0].name = "default";
  cases.cases[0].env = defaultProbeEnvironment();
  auto bad = probeGraph(*graph, ProbeOutput{node, "no_such_port"}, cases, GetParam(), diags);
  EXPECT_FALSE(bad);
  EXPECT_NE(core_test::dump(diags).find("has no output 'no_such_port'"), std::string::npos) << core_test::dump(diags);
}

INSTANTIATE_TEST_SUITE_P(Targets, ProbeOnGpu, ::testing::Values(Target::Glsl330, Target::Es300),
                         [](const auto& info) { return std::string(targetName(info.param)); });

}  // namespace
}  // namespace wg::accuracy

namespace wg::accuracy {
namespace {

std::string wg(const std::string& args, int* rc) {
  std::string out;
  *rc = test::runCommand(test::shellQuote(test::watergraphBinary()) + " " + args, &out);
  return out;
}

TEST(ProbeCli, PrintsGpuReferenceErrorsAndExitsZeroOnTheExampleCases) {
  int rc = 0;
  std::string out = wg("probe " + test::shellQuote(test::sourcePath("graphs/lake.json")) + " --cases " +
                           test::shellQuote(test::sourcePath("tests/hardcases/graphs.json")),
                       &rc);
  EXPECT_EQ(rc, 0) << out;
  for (const char* s : {"gpu (", "ref (", "abs ", "rel ", "nan/inf: gpu no, ref no", "cases passed"})
    EXPECT_NE(out.find(s), std::string::npos) << s << "\n" << out;
}

// mod by a divisor the graph computes as 0 (time - time): the documented 0 on the GPU too.
// The GL driver folds u_time - u_time to 0 and may then treat x / 0 and 0 * inf as
// finite, so a guard that tests the inf of the quotient gave x here (3.5), not 0.
TEST(ProbeCli, ModByAZeroTheGraphComputesIsZeroOnTheGpu) {
  std::string dir = test::makeTempDir("wg_mod0_");
  test::writeFile(dir + "/node.json", R"({"version": 1, "name": "n", "nodes": [
    {"id": "t", "type": "time"}, {"id": "z", "type": "sub", "inputs": {"a": "t.out", "b": "t.out"}},
    {"id": "m", "type": "mod", "inputs": {"x": "t.out", "y": "z.out"}}], "outputs": {"fragment": {"color": "m.out"}}})");
  test::writeFile(dir + "/formula.json", R"json({"version": 1, "name": "f", "nodes": [{"id": "t", "type": "time"},
    {"id": "x", "type": "expression", "options": {"inputs": {"a": "float"}, "formula": "mod(a, a - a) + mod(vec3(a), vec3(a - a))"},
     "inputs": {"a": "t.out"}}], "outputs": {"fragment": {"color": "x.out"}}})json");
  test::writeFile(dir + "/cases.json", R"({"cases": [{"name": "t35", "time": 3.5}, {"name": "t1", "time": 1}]})");
  for (const char* graph : {"node.json", "formula.json"})
    for (const char* target : {"glsl330", "es300"}) {
      SCOPED_TRACE(std::string(graph) + " " + target);
      int rc = 0;
      std::string out = wg("probe " + test::shellQuote(dir + "/" + graph) + " --cases " + test::shellQuote(dir + "/cases.json") +
                               " --target " + target,
                           &rc);
      EXPECT_EQ(rc, 0) << out;
      EXPECT_NE(out.find("gpu (0, 0, 0)"), std::string::npos) << out;
    }
  std::filesystem::remove_all(dir);
}

// A folder given as the cases file cannot be read (not a JSON syntax error); a case name
// with a control character would forge report lines; --options naming a key twice would
// silently take the last value.
TEST(ProbeCli, CasesFilesAndOptionsOfTheWrongKind) {
  std::string dir = test::makeTempDir("wg_probe_kind_");
  int rc = 0;
  std::string out = wg("probe --node pow --cases " + test::shellQuote(dir), &rc);
  EXPECT_EQ(rc, 2) << out;
  EXPECT_NE(out.find("[WG050] cannot read the cases file: it is not a regular file"), std::string::npos) << out;
  test::writeFile(dir + "/c.json", "{\"cases\": [{\"name\": \"a\\nb\\u001b[31mred\"}]}");
  out = wg("probe --node pow --cases " + test::shellQuote(dir + "/c.json"), &rc);
  EXPECT_EQ(rc, 1) << out;
  EXPECT_NE(out.find("[WG060]"), std::string::npos) << out;
  EXPECT_NE(out.find("control character"), std::string::npos) << out;
  EXPECT_EQ(out.find('\x1b'), std::string::npos) << "the escape reached the terminal";
  out = wg(R"(probe --node fresnel --sweep angle:0:90:10 --options '{"model": "exact", "model": "schlick"}')", &rc);
  EXPECT_EQ(rc, 2) << out;
  EXPECT_NE(out.find("duplicate key 'model'"), std::string::npos) << out;
  // --options with --cases was ignored (the cases give their own options): refused.
  test::writeFile(dir + "/x.json", R"({"cases": [{"name": "half", "inputs": {"x": 0.5}}]})");
  out = wg(R"(probe --node fresnel --options '{"model": "power"}' --cases )" + test::shellQuote(dir + "/x.json"), &rc);
  EXPECT_EQ(rc, 2) << out;
  EXPECT_NE(out.find("--options applies to --sweep"), std::string::npos) << out;
  std::filesystem::remove_all(dir);
}

// An expression's inputs are those its options declare: --sweep steps them (it said 'x'
// was no input of expression).
TEST(ProbeCli, AnExpressionsInputIsSwept) {
  int rc = 0;
  std::string out = wg(R"(probe --node expression --options '{"formula": "x * 2.0", "inputs": {"x": "float"}}' --sweep x:0:1:5)", &rc);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_NE(out.find("5 points, 0 over the bound"), std::string::npos) << out;
  out = wg(R"(probe --node expression --options '{"formula": "x * 2.0", "inputs": {"x": "float"}}' --sweep y:0:1:5)", &rc);
  EXPECT_EQ(rc, 2) << out;
  EXPECT_NE(out.find("'y' is neither 'angle', an input of expression (with these --options)"), std::string::npos) << out;
}

TEST(ProbeCli, ANodeAloneWithTheSuiteCases) {
  int rc = 0;
  std::string out = wg("probe --node pow --cases " + test::shellQuote(test::sourcePath("tests/hardcases/suite.json")), &rc);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_NE(out.find("output pow.out"), std::string::npos) << out;
  EXPECT_NE(out.find("ok    pow_zero_negative_exponent"), std::string::npos) << out;
  out = wg("probe --node no_such_node --cases " + test::shellQuote(test::sourcePath("tests/hardcases/suite.json")), &rc);
  EXPECT_EQ(rc, 2) << out;
}

TEST(ProbeCli, JsonOutputAndExitOneOnInfinity) {
  std::string dir = test::makeTempDir("wg_probe");
  test::writeFile(dir + "/d.json", R"({"version": 1, "name": "d", "parameters": {"b": {"type": "float", "default": 1}},
    "nodes": [{"id": "q", "type": "div", "inputs": {"a": 1, "b": "$b"}}], "outputs": {"fragment": {"alpha": "q.out"}}})");
  test::writeFile(dir + "/c.json", R"({"cases": [{"name": "zero", "parameters": {"b": 0}}]})");
  int rc = 0;
  std::string out = wg("probe " + test::shellQuote(dir + "/d.json") + " --output q.out --cases " +
                           test::shellQuote(dir + "/c.json") + " --target es300 --json",
                       &rc);
  EXPECT_EQ(rc, 1) << out;
  auto j = nlohmann::json::parse(out.substr(out.find('{')));
  EXPECT_EQ(j["cases"][0]["gpu"][0], "inf");
  EXPECT_EQ(j["cases"][0]["gpu_nan_inf"], true);
  EXPECT_EQ(j["passed"], false);
  // A bad cases file: file:line:col, exit 1.
  test::writeFile(dir + "/bad.json", "{\"cases\": [{\"name\": \"a\", \"time\": \"soon\"}]}");
  out = wg("probe " + test::shellQuote(dir + "/d.json") + " --cases " + test::shellQuote(dir + "/bad.json"), &rc);
  EXPECT_EQ(rc, 1) << out;
  EXPECT_NE(out.find("bad.json:1:34: error: [WG060] \"time\" must be a number"), std::string::npos) << out;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace wg::accuracy

namespace wg::accuracy {
namespace {

// probe GRAPH --preset NAME probes the graph as the preset makes it; check --preset too.
TEST(PresetCli, ProbeAndCheckApplyAPresetAndNameAMissingOne) {
  std::string dir = test::makeTempDir("wg_probe_preset");
  test::writeFile(dir + "/d.json", R"({"version": 1, "name": "d",
    "parameters": {"b": {"type": "float", "default": 1, "static": true}},
    "presets": {"half": {"b": 2}},
    "nodes": [{"id": "q", "type": "div", "inputs": {"a": 1, "b": "$b"}}], "outputs": {"fragment": {"alpha": "q.out"}}})");
  test::writeFile(dir + "/c.json", R"({"cases": [{"name": "at_rest"}]})");
  const std::string graph = test::shellQuote(dir + "/d.json"), cases = test::shellQuote(dir + "/c.json");
  auto gpuValue = [&](const std::string& extra) {
    std::string out, err;
    int rc = test::runCommandSplit(test::shellQuote(test::watergraphBinary()) + " probe " + graph +
                                       " --output q.out --cases " + cases + " --json" + extra,
                                   &out, &err);
    EXPECT_EQ(rc, 0) << out << err;
    return nlohmann::json::parse(out.substr(out.find('{')))["cases"][0]["gpu"][0].get<double>();
  };
  EXPECT_EQ(gpuValue(""), 1.0);
  EXPECT_EQ(gpuValue(" --preset half"), 0.5);

  int rc = 0;
  std::string out;
  rc = test::runCommand(test::shellQuote(test::watergraphBinary()) + " probe " + graph + " --cases " + cases +
                            " --preset stormy", &out);
  EXPECT_EQ(rc, 2) << out;
  EXPECT_NE(out.find("[WG052] graph 'd' has no preset 'stormy'; its presets: half"), std::string::npos) << out;
  rc = test::runCommand(test::shellQuote(test::watergraphBinary()) + " probe --node pow --cases " + cases +
                            " --preset half", &out);
  EXPECT_EQ(rc, 2) << out;
  EXPECT_NE(out.find("--preset needs a GRAPH"), std::string::npos) << out;
  rc = test::runCommand(test::shellQuote(test::watergraphBinary()) + " check " + graph + " --target glsl330 --size 16x9 --preset stormy",
                        &out);
  EXPECT_EQ(rc, 2) << out;
  EXPECT_NE(out.find("[WG052]"), std::string::npos) << out;
  rc = test::runCommand(test::shellQuote(test::watergraphBinary()) + " check " + graph + " --target glsl330 --size 16x9 --preset half",
                        &out);
  EXPECT_EQ(rc, 0) << out;
}

}  // namespace
}  // namespace wg::accuracy
