// Exponential inlining within the limits (docs/robustness.md, issue 40 class 1): sixteen
// small files, each level instancing the next twice with 64-character ids, inline to
// 196,609 nodes (under the 200,000-node limit) whose ids alone are 200 MB; `validate` took
// 4 min 45 s and 2.76 GB. The inlined size (each node's full id plus kInlinedNodeBytes) is
// predicted from the import tree before anything is inlined and held to kMaxInlinedBytes;
// the ops an expression expands into are held to the same budget as resolve makes them.
// bench/import_tree.py writes the same trees for measuring (bench/RESULTS.md).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "codegen/compile.h"
#include "codegen/emit_glsl.h"
#include "core/graph_imports.h"
#include "core/graph_io.h"
#include "core/load_limits.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg {
namespace {

// "<stem>_xxx...": an id of exactly `length` characters.
std::string longId(const std::string& stem, size_t length) { return (stem + "_" + std::string(length, 'x')).substr(0, length); }

struct Tree {
  int levels = 16;
  int fan = 2;           // instances of the next level in each level, in a chain
  int leafNodes = 3;     // the last level's nodes: a chain of `leaf` on the level's input
  size_t idLength = 64;
  std::string leaf = "{\"id\": \"ID\", \"type\": \"sin\", \"inputs\": {\"x\": \"IN\"}}";  // ID, IN replaced; output .out
};

std::string replaced(std::string s, const std::string& what, const std::string& with) {
  for (size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + with.size())) s.replace(at, what.size(), with);
  return s;
}

// Writes top.json and lib/l01.json ... lib/lNN.json into `dir`; returns top.json's path.
std::string writeTree(const std::string& dir, const Tree& t) {
  std::filesystem::create_directories(dir + "/lib");
  auto chain = [&](const std::string& type, const std::string& first, std::string* last) {
    std::string nodes, prev = first;
    for (int k = 0; k < t.fan; ++k) {
      std::string id = longId("i" + std::to_string(k), t.idLength);
      nodes += std::string(k ? ",\n" : "") + "{\"id\": \"" + id + "\", \"type\": \"" + type + "\", \"inputs\": {\"x\": \"" + prev + "\"}}";
      prev = id + ".v";
    }
    *last = prev;
    return nodes;
  };
  for (int level = 1; level <= t.levels; ++level) {
    std::string nodes, last;
    char next[16];
    std::snprintf(next, sizeof next, "l%02d.json", level + 1);
    if (level < t.levels) {
      nodes = chain("next", "$x", &last);
    } else {
      std::string prev = "$x";
      for (int k = 0; k < t.leafNodes; ++k) {
        std::string id = longId("m" + std::to_string(k), t.idLength);
        nodes += std::string(k ? ",\n" : "") + replaced(replaced(t.leaf, "ID", id), "IN", prev);
        prev = id + ".out";
      }
      last = prev;
    }
    char name[32];
    std::snprintf(name, sizeof name, "/lib/l%02d.json", level);
    test::writeFile(dir + name, "{\"version\": 1, \"name\": \"level" + std::to_string(level) +
                                    "\", \"parameters\": {\"x\": {\"type\": \"float\", \"default\": 0.5}},\n" +
                                    (level < t.levels ? "\"imports\": {\"next\": \"" + std::string(next) + "\"},\n" : "") +
                                    "\"interface\": {\"outputs\": {\"v\": {\"type\": \"float\", \"source\": \"" + last +
                                    "\"}}},\n\"nodes\": [\n" + nodes + "\n]}\n");
  }
  std::string time = longId("t", t.idLength), last;
  std::string nodes = chain("tree", time + ".out", &last);
  test::writeFile(dir + "/top.json", "{\"version\": 1, \"name\": \"top\", \"imports\": {\"tree\": \"lib/l01.json\"},\n\"nodes\": [\n{\"id\": \"" +
                                         time + "\", \"type\": \"time\"},\n" + nodes +
                                         "\n], \"outputs\": {\"fragment\": {\"alpha\": \"" + last + "\"}}}\n");
  return dir + "/top.json";
}

// The top-level graph as written, its imports not loaded.
std::optional<Graph> topOf(const std::string& path, Diagnostics& diags) {
  auto text = readGraphFile(path, diags);
  if (!text) return std::nullopt;
  return parseGraph(*text, path, diags);
}

const Diagnostic* firstError(const Diagnostics& diags) {
  for (const auto& d : diags.all())
    if (d.severity == Severity::Error) return &d;
  return nullptr;
}

TEST(ImportBudget, AnExponentialTreeWithinTheNodeLimitIsRefusedBeforeInlining) {
  std::string dir = test::makeTempDir("wg_tree_");
  std::string top = writeTree(dir, Tree{});
  Diagnostics diags;
  auto g = topOf(top, diags);
  ASSERT_TRUE(g);
  ASSERT_FALSE(loadImports(*g, diags));  // nothing inlined: the tree alone says so
  const Diagnostic* e = firstError(diags);
  ASSERT_TRUE(e);
  EXPECT_EQ(codeString(e->code), "WG035") << formatText(*e);
  EXPECT_EQ(e->where.file.str(), top);
  EXPECT_EQ(e->where.line, 4) << formatText(*e);  // the first instance: its half of the tree is already past
  EXPECT_NE(e->message.find("inlined size"), std::string::npos) << e->message;
  EXPECT_NE(e->message.find("32 MiB"), std::string::npos) << e->message;
  // Within the node limit: only the size refuses it.
  EXPECT_EQ(inlinedNodeCount(*g), 196609u);
  EXPECT_GT(inlinedSize(*g).bytes, kMaxInlinedBytes);
  // Through the CLI: one error line, exit 1.
  test::CmdResult r = test::runWatergraph("validate " + test::shellQuote(top));
  EXPECT_EQ(r.exit, 1) << r.err;
  EXPECT_NE(r.err.find("top.json:4:1: error: [WG035]"), std::string::npos) << r.err;
  std::filesystem::remove_all(dir);
}

TEST(ImportBudget, ThePredictionIsTheIdsTimesTheInstances) {
  // A level's nodes count once per instance, each with every instance's id before its own.
  std::string dir = test::makeTempDir("wg_tree_");
  Tree t;
  t.levels = 3;
  t.idLength = 10;
  Diagnostics diags;
  auto g = loadGraphFile(writeTree(dir, t), diags);
  ASSERT_TRUE(g) << formatText(diags.all().front());
  // 2 x 2 x 2 = 8 leaf chains of 3 nodes; each leaf id has three instance ids and '/' before it.
  const size_t leafBytes = 8 * 3 * (3 * (10 + 1) + 10 + kInlinedNodeBytes);
  const size_t timeBytes = 10 + kInlinedNodeBytes;
  EXPECT_EQ(inlinedSize(*g).nodes, 25u);
  EXPECT_EQ(inlinedSize(*g).bytes, leafBytes + timeBytes);
  // And that is what resolve makes: one op per node, ids as predicted.
  auto p = buildProgram(*g, defaultRegistry(), diags);
  ASSERT_TRUE(p);
  std::filesystem::remove_all(dir);
}

// The largest graph of this shape the budget allows compiles (in process: glslang's time on
// a 30,000-line shader is glslang's; bench/RESULTS.md has the CLI figures); one leaf node more
// is refused. A chain of single instances sixteen deep, so every leaf id is 1,104 bytes.
TEST(ImportBudget, AGraphJustUnderTheBudgetCompilesAndOneNodeMoreIsRefused) {
  std::string dir = test::makeTempDir("wg_tree_");
  Tree t;
  t.fan = 1;
  auto bytesWith = [&](int leafNodes) {
    t.leafNodes = leafNodes;
    Diagnostics d;
    auto g = loadGraphFile(writeTree(dir + "/n" + std::to_string(leafNodes), t), d);
    EXPECT_TRUE(g);
    return g ? inlinedSize(*g).bytes : 0;
  };
  const size_t one = bytesWith(1), perNode = bytesWith(2) - one;
  ASSERT_EQ(perNode, 16 * 65 + 64 + kInlinedNodeBytes);
  const int most = static_cast<int>((kMaxInlinedBytes - one) / perNode) + 1;
  t.leafNodes = most;
  std::string under = writeTree(dir + "/under", t);
  Diagnostics diags;
  auto g = loadGraphFile(under, diags);
  ASSERT_TRUE(g) << formatText(diags.all().front());
  EXPECT_LE(inlinedSize(*g).bytes, kMaxInlinedBytes);
  auto p = buildProgram(*g, defaultRegistry(), diags);
  ASSERT_TRUE(p) << (diags.all().empty() ? "" : formatText(diags.all().front()));
  EXPECT_EQ(p->ops.size(), static_cast<size_t>(most) + 1);  // the leaves and the time node
  EmitResult er = emitProgram(*p, Target::Vk450, "under.json");
  EXPECT_EQ(er.shaders.size(), 2u);

  t.leafNodes = most + 1;
  Diagnostics overDiags;
  EXPECT_FALSE(loadGraphFile(writeTree(dir + "/over", t), overDiags));
  ASSERT_TRUE(firstError(overDiags));
  EXPECT_EQ(codeString(firstError(overDiags)->code), "WG035");
  std::filesystem::remove_all(dir);
}

// An expression is one node to the prediction and many ops to resolve: a tree of formulas
// is held to the same budget as its ops are made, at the node that passes it.
TEST(ImportBudget, TheOpsOfExpressionsAreHeldToTheBudget) {
  std::string dir = test::makeTempDir("wg_tree_");
  Tree t;
  t.levels = 12;
  t.leafNodes = 1;
  std::string formula = "x";
  for (int k = 1; k <= 300; ++k) formula += " * 1.0001 + x";
  t.leaf = "{\"id\": \"ID\", \"type\": \"expression\", \"inputs\": {\"x\": \"IN\"}, \"options\": {\"inputs\": {\"x\": \"float\"}, "
           "\"formula\": \"" + formula + "\"}}";
  std::string top = writeTree(dir, t);
  Diagnostics diags;
  auto g = loadGraphFile(top, diags);
  ASSERT_TRUE(g) << formatText(diags.all().front());  // 4,096 expressions are few nodes
  EXPECT_LE(inlinedSize(*g).bytes, kMaxInlinedBytes);
  EXPECT_FALSE(buildProgram(*g, defaultRegistry(), diags));
  const Diagnostic* e = firstError(diags);
  ASSERT_TRUE(e);
  EXPECT_EQ(codeString(e->code), "WG035") << formatText(*e);
  EXPECT_NE(e->where.file.str().find("l12.json"), std::string::npos) << formatText(*e);
  EXPECT_NE(e->message.find("inlined size"), std::string::npos) << e->message;
  std::filesystem::remove_all(dir);
}

// vk450 through glslang and spirv-val, at two sizes of a tree whose leaves call a library
// function (tan): 1,536 and 6,144 calls, each with an argument temporary glslang names
// "param". spirv-val with friendly names was quadratic in such repeats (12,288 calls: 31 s
// against 0.4 s for glsl330); it runs without them now. What is compared here is sizes, not
// time: four times the calls give four times the SPIR-V and every stage validates; the
// times are in bench/RESULTS.md ("vk450 against glsl330").
TEST(ImportBudget, Vk450GrowsWithTheGraphLikeGlsl330) {
  std::string dir = test::makeTempDir("wg_tree_");
  size_t spirv[2] = {0, 0};
  for (int i = 0; i < 2; ++i) {
    Tree t;
    t.levels = i == 0 ? 9 : 11;
    t.idLength = 8;
    t.leaf = "{\"id\": \"ID\", \"type\": \"tan\", \"inputs\": {\"x\": \"IN\"}}";
    Diagnostics diags;
    auto g = loadGraphFile(writeTree(dir + "/" + std::to_string(i), t), diags);
    ASSERT_TRUE(g);
    ASSERT_EQ(inlinedNodeCount(*g), (i == 0 ? 1536u : 6144u) + 1);
    CompileOptions options;
    options.targets = {Target::Glsl330, Target::Vk450};
    auto r = compileGraph(*g, defaultRegistry(), options, diags);
    ASSERT_TRUE(r) << (diags.all().empty() ? "" : formatText(diags.all().front()));
    for (const auto& f : r->files)
      if (f.name.size() > 9 && f.name.compare(f.name.size() - 9, 9, ".frag.spv") == 0) spirv[i] = f.contents.size();
  }
  ASSERT_GT(spirv[0], 0u);
  const double ratio = static_cast<double>(spirv[1]) / static_cast<double>(spirv[0]);
  EXPECT_GT(ratio, 3.5);
  EXPECT_LT(ratio, 4.5);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace wg
