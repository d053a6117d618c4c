// Limits (docs/robustness.md): each limit is accepted at its value and refused one past it
// with WG035 (or WG030 for an option's own limit) at a position in the file; and input size
// never turns into recursion depth: a 100,000-node chain loads, resolves, runs every pass
// and is emitted without a stack overflow.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "codegen/compile.h"
#include "codegen/emit_glsl.h"
#include "core/graph_io.h"
#include "core/json_source.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg {
namespace {

using Clock = std::chrono::steady_clock;

using test::secondsSince;

// The first error's code string, or "" when there is none.
std::string firstCode(const Diagnostics& diags) {
  for (const auto& d : diags.sorted())
    if (d.severity == Severity::Error) return codeString(d.code);
  return "";
}

std::string graphWithNodes(const std::string& nodes, const std::string& outputs) {
  return "{\"version\": 1, \"name\": \"g\", \"nodes\": [" + nodes + "], \"outputs\": " + outputs + "}";
}

// a0 = time; a_i = sin(a_{i-1}); output alpha = a_{n-1} (or a0 when `pruned`).
std::string chainGraph(int n, bool pruned) {
  std::string s = "{\"version\": 1, \"name\": \"chain\", \"nodes\": [\n{\"id\": \"a0\", \"type\": \"time\"}";
  s.reserve(static_cast<size_t>(n) * 60);
  for (int i = 1; i < n; ++i)
    s += ",\n{\"id\": \"a" + std::to_string(i) + "\", \"type\": \"sin\", \"inputs\": {\"x\": \"a" +
         std::to_string(i - 1) + ".out\"}}";
  s += "\n], \"outputs\": {\"fragment\": {\"alpha\": \"a" + std::to_string(pruned ? 0 : n - 1) + ".out\"}}}\n";
  return s;
}

TEST(Limits, FileSize) {
  std::string big(16u * 1024u * 1024u + 1u, ' ');
  Diagnostics diags;
  EXPECT_FALSE(parseGraph(big, "big.json", diags));
  EXPECT_EQ(firstCode(diags), "WG035");
  // A text the caller holds shared is refused the same way, and not kept.
  Diagnostics sharedDiags;
  EXPECT_FALSE(parseGraph(std::make_shared<const std::string>(big), "big.json", sharedDiags));
  EXPECT_EQ(firstCode(sharedDiags), "WG035");
  EXPECT_EQ(sharedDiags.source("big.json"), nullptr);
  // Through the file reader too: it stops reading past the limit.
  std::string dir = test::makeTempDir("wg_limits_");
  test::writeFile(dir + "/big.json", big);
  Diagnostics fileDiags;
  EXPECT_FALSE(loadGraphFile(dir + "/big.json", fileDiags));
  EXPECT_EQ(firstCode(fileDiags), "WG035");
  ASSERT_FALSE(fileDiags.all().empty());
  EXPECT_NE(formatText(fileDiags.all().front()).find("16 MiB"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(Limits, NodeCount) {
  // 200,000 nodes are allowed; one more is refused at "nodes" before any node is looked at.
  std::string nodes;
  nodes.reserve(200001 * 3);
  for (int i = 0; i < 200001; ++i) nodes += i ? ",{}" : "{}";
  Diagnostics diags;
  EXPECT_FALSE(parseGraph(graphWithNodes(nodes, "{}"), "many.json", diags));
  auto sorted = diags.sorted();
  ASSERT_FALSE(sorted.empty());
  EXPECT_EQ(codeString(sorted.front().code), "WG035") << formatText(sorted.front());
  EXPECT_EQ(sorted.front().where.line, 1);
  EXPECT_EQ(sorted.front().where.col, 38);  // the '[' after "nodes": (graphWithNodes)
  EXPECT_EQ(diags.errorCount(), 1u);       // the limit alone: not 200,001 node errors
}

TEST(Limits, StringLength) {
  std::string ok(4096, 'd'), tooLong(4097, 'd');
  auto withDescription = [](const std::string& d) {
    return "{\"version\": 1, \"name\": \"g\", \"description\": \"" + d +
           "\", \"nodes\": [], \"outputs\": {\"fragment\": {\"alpha\": 1}}}";
  };
  Diagnostics a, b;
  EXPECT_TRUE(parseGraph(withDescription(ok), "s.json", a)) << firstCode(a);
  EXPECT_FALSE(parseGraph(withDescription(tooLong), "s.json", b));
  EXPECT_EQ(firstCode(b), "WG035");
}

TEST(Limits, NestingDepth) {
  // 64 levels of JSON nesting parse; the 65th opening bracket is refused where it is.
  auto nested = [](int depth) { return std::string(depth, '[') + std::string(depth, ']'); };
  Diagnostics a, b;
  EXPECT_TRUE(parseJsonWithPositions(nested(64), "d.json", a));
  EXPECT_FALSE(parseJsonWithPositions(nested(65), "d.json", b));
  ASSERT_EQ(firstCode(b), "WG035");
  EXPECT_EQ(b.sorted().front().where.col, 65);
  // A very deep file is refused at depth 65 without recursing into the rest.
  Diagnostics c;
  EXPECT_FALSE(parseJsonWithPositions(nested(1000000), "d.json", c));
  EXPECT_EQ(firstCode(c), "WG035");
}

TEST(Limits, WaveCount) {
  auto waves = [](int n) {
    std::string w;
    for (int i = 0; i < n; ++i)
      w += std::string(i ? ", " : "") + "{\"direction\": [1, " + std::to_string(i) +
           "], \"steepness\": 0.01, \"wavelength\": 10}";
    return graphWithNodes("{\"id\": \"w\", \"type\": \"gerstner_waves\", \"options\": {\"waves\": [" + w + "]}}",
                          "{\"vertex\": {\"position\": \"w.position\"}}");
  };
  for (int n : {1, 16, 17}) {
    Diagnostics diags;
    auto g = parseGraph(waves(n), "w.json", diags);
    ASSERT_TRUE(g) << firstCode(diags);
    auto p = buildProgram(*g, defaultRegistry(), diags);
    if (n <= 16)
      EXPECT_TRUE(p) << n << " waves: " << firstCode(diags);
    else
      EXPECT_EQ(firstCode(diags), "WG030") << n << " waves";
  }
}

// Fan-in needs no limit of its own: a node's inputs are its type's ports (a fixed, small
// number; anything else is WG021). Fan-out (one output feeding many inputs) is bounded by
// the node count, and a value is computed once into a temporary, never re-expanded per use:
// a "diamond" chain where each node uses the previous one twice stays linear in size.
TEST(Limits, FanOutStaysLinear) {
  auto diamond = [](int n) {
    std::string nodes = "{\"id\": \"a0\", \"type\": \"time\"}";
    for (int i = 1; i < n; ++i)
      nodes += ", {\"id\": \"a" + std::to_string(i) + "\", \"type\": \"add\", \"inputs\": {\"a\": \"a" +
               std::to_string(i - 1) + ".out\", \"b\": \"a" + std::to_string(i - 1) + ".out\"}}";
    return graphWithNodes(nodes, "{\"fragment\": {\"alpha\": \"a" + std::to_string(n - 1) + ".out\"}}");
  };
  size_t size100 = 0, size200 = 0;
  for (int n : {100, 200}) {
    Diagnostics diags;
    auto g = parseGraph(diamond(n), "d.json", diags);
    ASSERT_TRUE(g);
    CompileOptions options;
    auto r = compileGraph(*g, defaultRegistry(), options, diags);  // glslang included
    ASSERT_TRUE(r) << firstCode(diags);
    size_t total = 0;
    for (const auto& f : r->files) total += f.contents.size();
    (n == 100 ? size100 : size200) = total;
  }
  EXPECT_LT(size200, size100 * 3) << "output grows faster than the graph";
  // Many users of one node: 10,000 nodes reading the same time.
  std::string nodes = "{\"id\": \"t\", \"type\": \"time\"}, {\"id\": \"s0\", \"type\": \"sin\", \"inputs\": {\"x\": \"t.out\"}}";
  for (int i = 1; i < 10000; ++i)
    nodes += ", {\"id\": \"s" + std::to_string(i) + "\", \"type\": \"add\", \"inputs\": {\"a\": \"s" +
             std::to_string(i - 1) + ".out\", \"b\": \"t.out\"}}";
  Diagnostics diags;
  auto g = parseGraph(graphWithNodes(nodes, "{\"fragment\": {\"alpha\": \"s9999.out\"}}"), "f.json", diags);
  ASSERT_TRUE(g);
  auto t0 = Clock::now();
  auto p = buildProgram(*g, defaultRegistry(), diags);
  ASSERT_TRUE(p) << firstCode(diags);
  EmitResult er = emitProgram(*p, Target::Vk450, "f.json");
  ASSERT_EQ(er.shaders.size(), 2u);
  EXPECT_LT(er.shaders[1].text.size(), 10000u * 200u);
  std::printf("fan-out 10,000: resolve + passes + emit %.2f s\n", secondsSince(t0));
}

// The 100,000-node chain, in process, without glslang (whose time on a 100,000-line
// shader is the glslang's, ~1 min for three targets; the CLI test below compiles a pruned
// chain of the same size and a full 2,000-node one). Any recursion whose depth followed
// the chain would overflow the stack here (and sooner under AddressSanitizer).
TEST(Limits, HundredThousandNodeChainHasNoDeepRecursion) {
  const int n = 100000;
  std::string text = chainGraph(n, false);
  auto t0 = Clock::now();
  Diagnostics diags;
  auto g = parseGraph(text, "chain.json", diags);
  ASSERT_TRUE(g) << firstCode(diags);
  double load = secondsSince(t0);
  t0 = Clock::now();
  auto p = buildProgram(*g, defaultRegistry(), diags);
  ASSERT_TRUE(p) << firstCode(diags);
  double passes = secondsSince(t0);
  EXPECT_EQ(p->ops.size(), static_cast<size_t>(n));
  t0 = Clock::now();
  EmitResult er = emitProgram(*p, Target::Glsl330, "chain.json");
  double emit = secondsSince(t0);
  ASSERT_EQ(er.shaders.size(), 2u);
  EXPECT_GT(er.shaders[1].text.size(), static_cast<size_t>(n) * 10);
  std::string canonical = saveGraph(*g);
  EXPECT_GT(canonical.size(), text.size() / 2);
  std::printf("100,000-node chain: load %.2f s, resolve + passes %.2f s, emit glsl330 %.2f s\n", load, passes, emit);
}

TEST(Limits, HundredThousandNodeChainThroughTheCli) {
  std::string dir = test::makeTempDir("wg_chain_");
  test::writeFile(dir + "/pruned.json", chainGraph(100000, true));
  test::writeFile(dir + "/full.json", chainGraph(2000, false));
  std::string out;
  auto t0 = Clock::now();
  int code = test::runCommand(test::watergraphBinary() + " compile " + dir + "/pruned.json -o " + dir + "/out", &out);
  double pruned = secondsSince(t0);
  EXPECT_EQ(code, 0) << out;
  EXPECT_TRUE(std::filesystem::exists(dir + "/out/pruned.manifest.json"));
  t0 = Clock::now();
  code = test::runCommand(test::watergraphBinary() + " validate " + dir + "/full.json", &out);
  double full = secondsSince(t0);
  EXPECT_EQ(code, 0) << out;
  std::printf("CLI: 100,000-node chain pruned to 1 node %.2f s; 2,000-node chain, 3 targets %.2f s\n", pruned, full);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace wg
