// The same graph always yields byte-identical output: in one process, across processes
// (the watergraph binary run twice), GLSL, SPIR-V and manifest alike.
#include <gtest/gtest.h>

#include <filesystem>

#include "codegen/compile.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg {
namespace {

namespace fs = std::filesystem;

std::vector<OutputFile> compileFile(const std::string& path) {
  Diagnostics diags;
  auto graph = loadGraphFile(path, diags);
  if (!graph) return {};
  auto result = compileGraph(*graph, defaultRegistry(), CompileOptions{}, diags);
  if (!result) return {};
  return result->files;
}

TEST(Determinism, InProcessCompilesAreByteIdentical) {
  auto graphs = test::exampleGraphs();
  ASSERT_FALSE(graphs.empty());
  for (const auto& g : graphs) {
    SCOPED_TRACE(g);
    auto first = compileFile(g);
    ASSERT_FALSE(first.empty()) << g << " does not compile";
    // Something else in between, so no state can carry the first result over unnoticed.
    for (const auto& other : graphs) compileFile(other);
    auto second = compileFile(g);
    ASSERT_EQ(first.size(), second.size());
    bool spv = false;
    for (size_t i = 0; i < first.size(); ++i) {
      EXPECT_EQ(first[i].name, second[i].name);
      EXPECT_TRUE(first[i].contents == second[i].contents) << first[i].name << " differs between two compiles";
      spv |= first[i].name.size() > 4 && first[i].name.substr(first[i].name.size() - 4) == ".spv";
    }
    EXPECT_TRUE(spv) << "no SPIR-V among the outputs";
  }
}

TEST(Determinism, TwoRunsOfTheBinaryWriteIdenticalFiles) {
  std::string args;
  for (const auto& g : test::exampleGraphs()) args += " " + test::shellQuote(g);
  std::string a = test::makeTempDir("wg_det_a_"), b = test::makeTempDir("wg_det_b_");
  std::string out;
  std::string bin = test::shellQuote(test::watergraphBinary());
  ASSERT_EQ(test::runCommand(bin + " compile" + args + " --subdirs -o " + test::shellQuote(a), &out), 0) << out;
  ASSERT_EQ(test::runCommand(bin + " compile" + args + " --subdirs -o " + test::shellQuote(b), &out), 0) << out;
  auto files = test::listFilesRecursive(a);
  EXPECT_FALSE(files.empty());
  EXPECT_EQ(files, test::listFilesRecursive(b));
  for (const auto& f : files) EXPECT_TRUE(test::readFile(a + "/" + f) == test::readFile(b + "/" + f)) << f;
  std::error_code ec;
  fs::remove_all(a, ec);
  fs::remove_all(b, ec);
}

TEST(Determinism, BinaryMatchesInProcessCompile) {
  for (const auto& g : test::exampleGraphs()) {
    SCOPED_TRACE(g);
    std::string dir = test::makeTempDir("wg_det_c_");
    std::string out;
    ASSERT_EQ(test::runCommand(test::shellQuote(test::watergraphBinary()) + " compile " + test::shellQuote(g) + " -o " +
                                   test::shellQuote(dir),
                               &out),
              0)
        << out;
    auto files = compileFile(g);
    std::vector<std::string> names;
    for (const auto& f : files) {
      names.push_back(f.name);
      EXPECT_TRUE(test::readFile(dir + "/" + f.name) == f.contents) << f.name;
    }
    std::sort(names.begin(), names.end());
    EXPECT_EQ(test::listFilesRecursive(dir), names);
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
}

}  // namespace
}  // namespace wg
