// The hard-case sweep of GLSL function nodes (accuracy/function_sweep.h): each input port
// over the suite's value classes for its type, the node's GLSL run on the GPU (glsl330 and
// es300 on GL, vk450 on Vulkan under the validation layer), every output checked for
// NaN/Inf, and against the reference formula where the node has one. A NaN is named by
// node, output, port and input class; a clean function passes; every case reaches the GPU;
// the example graphs' function nodes pass; `probe GRAPH --functions` exits as the suite.
#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "accuracy/function_sweep.h"
#include "accuracy/gpu_executor.h"
#include "core/graph_io.h"
#include "suite_file.h"
#include "test_support.h"

namespace wg::accuracy {
namespace {

// A folder holding one graph of glsl_function nodes over the file `file.glsl`.
struct SweepTree : test::FileTree {
  SweepTree(const std::string& glsl, const std::string& nodes, const std::string& color) : FileTree("wg_function_sweep") {
    write("file.glsl", glsl);
    graphPath = write("g.json", test::graphJson(nodes, R"("fragment": {"color": )" + color + "}"));
  }
  std::string graphPath;
};

std::vector<FunctionNodeUnderTest> nodesOf(const std::string& graphPath) {
  Diagnostics diags;
  auto graph = loadGraphFile(graphPath, diags);
  std::optional<std::vector<FunctionNodeUnderTest>> nodes;
  if (graph) nodes = functionNodesOf(*graph, diags);
  std::string why;
  for (const auto& d : diags.all()) why += formatText(d) + "\n";
  EXPECT_TRUE(nodes) << why;
  return nodes ? *nodes : std::vector<FunctionNodeUnderTest>{};
}

std::string functionNode(const std::string& id, const std::string& function, const std::string& inputs,
                         const std::string& reference = "") {
  return R"({"id": ")" + id + R"(", "type": "glsl_function", "options": {"file": "file.glsl", "function": ")" +
         function + "\"" + (reference.empty() ? "" : R"(, "reference": )" + reference) + R"(}, "inputs": )" + inputs +
         "}";
}

const char* kNanFunctions = R"(// NaN where the suite's classes reach: the zero vector, a negative argument.
vec3 direction(vec3 v) { return v / length(v); }
float root(float x) { return sqrt(x); }
)";

const char* kCleanFunctions = R"(// Finite for every finite input.
float soft(float x, vec2 p) { return x / (1.0 + abs(x)) + 0.25 * sin(clamp(p.x, -100.0, 100.0)); }
float blend(float a, float b) { return 0.25 * a + 0.75 * b; }
)";

bool hasLine(const std::vector<std::string>& lines, const std::vector<std::string>& parts) {
  for (const auto& l : lines) {
    bool all = true;
    for (const auto& p : parts) all &= l.find(p) != std::string::npos;
    if (all) return true;
  }
  return false;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += l + "\n";
  return s;
}

class FunctionSweepOnGpu : public ::testing::TestWithParam<Target> {
 protected:
  std::unique_ptr<GpuExecutor> executor() {
    ExecutorOptions o;
    o.vulkanValidation = GetParam() == Target::Vk450;
    return makeGpuExecutor(GetParam(), o);
  }
  FunctionSweepResult sweep(const std::vector<FunctionNodeUnderTest>& nodes) {
    auto gpu = executor();
    FunctionSweepResult r = sweepFunctionNodes(nodes, test_suite::loadSuite(), *gpu);
    gpu->finish();
    return r;
  }
};

TEST_P(FunctionSweepOnGpu, CatchesANaNNamingTheNodeThePortAndTheInputClass) {
  std::string nodes = functionNode("dir", "direction", R"({"v": [0, 1, 0]})") + ",\n" +
                      functionNode("root", "root", R"({"x": 2})") + R"(,
    {"id": "sum", "type": "add", "inputs": {"a": "dir.out", "b": "root.out"}})";
  SweepTree tree(kNanFunctions, nodes, "\"sum.out\"");
  FunctionSweepResult r = sweep(nodesOf(tree.graphPath));
  EXPECT_EQ(r.nodes, 2);
  EXPECT_TRUE(r.errors.empty()) << joined(r.errors);
  EXPECT_GT(r.nanInf, 0);
  EXPECT_EQ(r.failures, r.nanInf);
  // The zero vector is the suite's case zero_normal (its input 'normal'); -1 is first given by negative_thickness.
  EXPECT_TRUE(hasLine(r.failureLines, {"node 'dir'", "output 'out'", "port 'v'", "case 'zero_normal.normal'", "GPU NaN/Inf"}))
      << joined(r.failureLines);
  EXPECT_TRUE(hasLine(r.failureLines, {"node 'root'", "port 'x'", "case 'negative_thickness.depth'", "GPU NaN/Inf"}))
      << joined(r.failureLines);
  // A positive argument and a non-zero vector stay finite: only the classes that reach the pole fail.
  for (const auto& c : r.cases)
    if (c.node.find("'root'") != std::string::npos && c.input[0] > 0) {
      EXPECT_EQ(c.failure, "") << c.inputClass;
    }
  EXPECT_TRUE(hasLine(r.notes, {"node 'dir'", "has no double reference"})) << joined(r.notes);
}

TEST_P(FunctionSweepOnGpu, ACleanFunctionPassesWithAndWithoutAReference) {
  std::string nodes = functionNode("s", "soft", R"({"x": 0.5, "p": [0, 0]})") + ",\n" +
                      functionNode("b", "blend", R"({"a": 1, "b": 2})", R"({"out": "0.25 * a + 0.75 * b"})") + R"(,
    {"id": "sum", "type": "add", "inputs": {"a": "s.out", "b": "b.out"}})";
  SweepTree tree(kCleanFunctions, nodes, "\"sum.out\"");
  FunctionSweepResult r = sweep(nodesOf(tree.graphPath));
  EXPECT_EQ(r.nodes, 2);
  EXPECT_TRUE(r.errors.empty()) << joined(r.errors);
  EXPECT_EQ(r.failures, 0) << joined(r.failureLines);
  EXPECT_EQ(r.nanInf, 0);
  // Only blend's runs are held to a reference: one per class of its two float ports.
  EXPECT_EQ(r.compared, 2 * static_cast<int>(functionInputClasses(test_suite::loadSuite(), Type::Float).size()));
  EXPECT_GT(r.caseRuns, r.compared);
}

// A reference that disagrees with the GLSL fails by the probe's error comparison, not by NaN.
TEST_P(FunctionSweepOnGpu, AReferenceFormulaIsComparedToo) {
  SweepTree tree(kCleanFunctions, functionNode("b", "blend", R"({"a": 1, "b": 2})", R"({"out": "0.5 * a + 0.5 * b"})"),
                 "\"b.out\"");
  FunctionSweepResult r = sweep(nodesOf(tree.graphPath));
  EXPECT_GT(r.failures, 0);
  EXPECT_EQ(r.nanInf, 0);
  EXPECT_TRUE(hasLine(r.failureLines, {"node 'b'", "port 'a'", "error "})) << joined(r.failureLines);
}

// A sine of a huge phase: float32 rounds the phase (x times 2 pi) by more than the bound's
// 1e-5 past x = 10^4, which the suite's huge classes reach. Held to the bare bound it fails
// there; with the rounding the function's arithmetic does (input_roundings) its bound
// follows the conditioning and it passes, while a wrong constant still fails at x = 1.
TEST_P(FunctionSweepOnGpu, InputRoundingsFollowTheConditioningOfAReference) {
  const char* glsl = "float wave(float x) { return sin(x * 6.28318530718); }\n";
  auto run = [&](const std::string& roundings, const std::string& formula) {
    std::string node = R"({"id": "w", "type": "glsl_function", "options": {"file": "file.glsl", "function": "wave", )" +
                       roundings + R"("reference": {"out": ")" + formula + R"("}}, "inputs": {"x": 1}})";
    SweepTree tree(glsl, node, "\"w.out\"");
    return sweep(nodesOf(tree.graphPath));
  };
  FunctionSweepResult bare = run("", "sin(x * 6.28318530718)");
  EXPECT_GT(bare.failures, 0);
  EXPECT_EQ(bare.nanInf, 0);
  EXPECT_TRUE(hasLine(bare.failureLines, {"port 'x' case 'time_1000000.time'", "error "})) << joined(bare.failureLines);
  for (const auto& c : bare.cases)
    if (!c.failure.empty()) {
      EXPECT_GE(std::fabs(c.input[0]), 100.0) << c.inputClass << ": " << c.failure;
    }

  FunctionSweepResult rounded = run(R"("input_roundings": 2, )", "sin(x * 6.28318530718)");
  EXPECT_EQ(rounded.failures, 0) << joined(rounded.failureLines);
  EXPECT_EQ(rounded.compared, rounded.caseRuns);

  FunctionSweepResult wrong = run(R"("input_roundings": 2, )", "sin(x * 6.2832)");
  int wrongWhereWellConditioned = 0;  // |x| <= 10: the phase keeps six digits there
  for (const auto& c : wrong.cases)
    if (!c.failure.empty() && std::fabs(c.input[0]) <= 10.0 && c.failure.starts_with("error ")) ++wrongWhereWellConditioned;
  EXPECT_GT(wrongWhereWellConditioned, 0) << joined(wrong.failureLines);
}

// Every (port, class) case reaches the GPU: an identity function hands each class's value
// back through its out parameter, per output, and the others' held value beside it.
TEST_P(FunctionSweepOnGpu, EveryCaseReachesTheGpu) {
  SweepTree tree("void pass(float x, vec3 v, out float xo, out vec3 vo) { xo = x; vo = v; }\n",
                 functionNode("p", "pass", R"({"x": 1, "v": [1, 2, 3]})") +
                     R"(, {"id": "m", "type": "mul", "inputs": {"a": "p.vo", "b": "p.xo"}})",
                 "\"m.out\"");
  ProbeCaseFile suite = test_suite::loadSuite();
  const size_t floats = functionInputClasses(suite, Type::Float).size();
  const size_t vec3s = functionInputClasses(suite, Type::Vec3).size();
  ASSERT_GE(floats, 20u);  // the suite's float classes: zero, negatives, huge, tiny, the poles
  ASSERT_GT(vec3s, floats);  // its vec3 classes and the floats splatted
  FunctionSweepResult r = sweep(nodesOf(tree.graphPath));
  ASSERT_TRUE(r.errors.empty()) << joined(r.errors);
  EXPECT_EQ(r.caseRuns, static_cast<int>(2 * (floats + vec3s)));  // two outputs
  ASSERT_EQ(r.cases.size(), static_cast<size_t>(r.caseRuns));
  for (const auto& c : r.cases) {
    bool own = (c.output == "xo") == (c.port == "x");  // the output that carries the swept port
    ASSERT_EQ(c.components, c.output == "xo" ? 1 : 3);
    for (int k = 0; k < c.components; ++k)
      EXPECT_EQ(c.gpu[static_cast<size_t>(k)], own ? c.input[k] : 0.5)
          << c.output << " " << c.port << "=" << c.inputClass << " component " << k;
  }
}

// The function nodes of the example graphs (in subgraphs too: caustic_pool's caustic light
// is a subgraph instance) are swept clean.
TEST_P(FunctionSweepOnGpu, ExampleGraphsFunctionNodesAreFinite) {
  int swept = 0;
  for (const auto& path : test::exampleGraphs()) {
    if (!test::holdsGlslFunction(path)) continue;
    std::vector<FunctionNodeUnderTest> nodes = nodesOf(path);
    EXPECT_FALSE(nodes.empty()) << path;
    FunctionSweepResult r = sweep(nodes);
    for (const auto& e : r.errors) ADD_FAILURE() << path << ": " << e;
    for (const auto& f : r.failureLines) ADD_FAILURE() << path << ": " << f;
    EXPECT_GT(r.caseRuns, 0) << path;
    swept += r.nodes;
    std::printf("[ function ] %s on %s: %s", path.c_str(), std::string(targetName(GetParam())).c_str(),
                formatFunctionSweep(r).c_str());
  }
  EXPECT_GE(swept, 1);
}

INSTANTIATE_TEST_SUITE_P(Targets, FunctionSweepOnGpu, ::testing::Values(Target::Glsl330, Target::Es300, Target::Vk450),
                         [](const auto& info) { return std::string(targetName(info.param)); });

TEST(FunctionSweep, InputClassesComeFromTheSuiteEachOnceAndFinite) {
  ProbeCaseFile suite = test_suite::loadSuite();
  for (Type t : {Type::Float, Type::Vec2, Type::Vec3, Type::Vec4, Type::Mat3}) {
    std::vector<FunctionInputClass> classes = functionInputClasses(suite, t);
    EXPECT_FALSE(classes.empty()) << typeName(t);
    bool zero = false;
    for (size_t i = 0; i < classes.size(); ++i) {
      EXPECT_EQ(classes[i].value.type, t);
      EXPECT_TRUE(classes[i].value.allFinite()) << classes[i].name;
      for (size_t j = 0; j < i; ++j) EXPECT_FALSE(classes[i].value == classes[j].value) << classes[i].name;
      zero |= classes[i].value == Value::ofType(t, 0.0);
    }
    EXPECT_TRUE(zero) << typeName(t) << " has no zero class";
  }
}

// A sampler2D parameter is held at a built-in texture (the node's, else its option's default),
// a matrix input is swept over the float classes splatted, and a matrix output, which a
// probe pixel cannot hold, is named as not read back.
TEST(FunctionSweep, SamplersAreHeldAndMatrixOutputsNoted) {
  std::string nodes = R"({"id": "a", "type": "glsl_function",
       "options": {"file": "file.glsl", "function": "tinted", "tex": "builtin:foam"},
       "inputs": {"uv": [0.5, 0.5], "m": "s.out", "k": 1}},
     {"id": "s", "type": "glsl_function", "options": {"file": "file.glsl", "function": "scaled"}, "inputs": {"k": 2}},
     {"id": "rgb", "type": "swizzle", "options": {"mask": "rgb"}, "inputs": {"x": "a.out"}})";
  SweepTree tree(R"(vec4 tinted(sampler2D tex, vec2 uv, mat3 m, float k) { return vec4(m * texture(tex, uv).rgb * k, 1.0); }
mat3 scaled(float k) { return mat3(k); }
)",
                 nodes, "\"rgb.out\"");
  auto gpu = makeGpuExecutor(Target::Glsl330);
  ProbeCaseFile suite = test_suite::loadSuite();
  FunctionSweepResult r = sweepFunctionNodes(nodesOf(tree.graphPath), suite, *gpu);
  EXPECT_TRUE(r.errors.empty()) << joined(r.errors);
  EXPECT_TRUE(hasLine(r.notes, {"node 'a'", "sampler2D 'tex' is held at the texture builtin:foam"})) << joined(r.notes);
  EXPECT_TRUE(hasLine(r.notes, {"node 's'", "output 'out' is a mat3", "not read back"})) << joined(r.notes);
  size_t expected = functionInputClasses(suite, Type::Vec2).size() + functionInputClasses(suite, Type::Mat3).size() +
                    functionInputClasses(suite, Type::Float).size();
  EXPECT_EQ(r.caseRuns, static_cast<int>(expected));  // node a's three inputs; node s has no output to read
  EXPECT_EQ(r.failures, 0) << joined(r.failureLines);
}

TEST(FunctionSweepCli, ExitsOneNamingThePortAndCaseAndZeroWhenClean) {
  const std::string suite = test::shellQuote(test::sourcePath("tests/hardcases/suite.json"));
  SweepTree bad(kNanFunctions, functionNode("root", "root", R"({"x": 2})"), "\"root.out\"");
  test::CmdResult r = test::runWatergraph("probe " + test::shellQuote(bad.graphPath) + " --functions --cases " + suite);
  EXPECT_EQ(r.exit, 1) << r.err;
  EXPECT_NE(r.err.find("port 'x' case 'negative_thickness.depth' -1: GPU NaN/Inf"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("has no double reference"), std::string::npos) << r.err;

  SweepTree clean(kCleanFunctions, functionNode("b", "blend", R"({"a": 1, "b": 2})", R"({"out": "0.25 * a + 0.75 * b"})"),
                  "\"b.out\"");
  r = test::runWatergraph("probe " + test::shellQuote(clean.graphPath) + " --functions --cases " + suite);
  EXPECT_EQ(r.exit, 0) << r.err;
  EXPECT_NE(r.err.find("1 function node on glsl330:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("0 failed (0 NaN/Inf)"), std::string::npos) << r.err;

  r = test::runWatergraph("probe --node fresnel --functions --cases " + suite);
  EXPECT_EQ(r.exit, 2) << r.err;
}

}  // namespace
}  // namespace wg::accuracy
