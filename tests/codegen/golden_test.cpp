// Golden files: the GLSL and manifest of every example graph, byte for byte, in
// tests/golden/<graph>/, and its WGSL module (compiled with the wgsl target, which adds it to
// the manifest: a second compile, GoldenWgsl) where the graph has one. SPIR-V (.spv) is
// binary and left out; determinism_test covers it.
// With WG_UPDATE_GOLDEN=1 the test rewrites the golden files (and removes stale ones)
// instead of failing; see tests/golden/README.md.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "codegen/compile.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg {
namespace {

namespace fs = std::filesystem;

std::string goldenDir() { return test::sourcePath("tests/golden"); }

std::vector<std::string> graphNames() {
  std::vector<std::string> names;
  for (const auto& path : test::exampleGraphs()) names.push_back(fs::path(path).stem().string());
  return names;
}

// SPIR-V is binary; an es300 stage's ".body" is its golden's text after the version line
// (Manifest.Es300StagesComeWithTheirBodiesAndVersion checks it), so not kept twice.
bool isGolden(const std::string& fileName) { return !fileName.ends_with(".spv") && !fileName.ends_with(".body"); }
// The WGSL module's golden is GoldenWgsl's.
bool isWgslGolden(const std::string& fileName) { return fileName.ends_with(".wgsl"); }

// "line N: expected ... / actual ..." for the first differing line.
std::string firstDifference(const std::string& expected, const std::string& actual) {
  auto e = test::splitLines(expected), a = test::splitLines(actual);
  for (size_t i = 0; i < std::max(e.size(), a.size()); ++i) {
    std::string el = i < e.size() ? e[i] : "<end of file>", al = i < a.size() ? a[i] : "<end of file>";
    if (el != al) return "first difference at line " + std::to_string(i + 1) + ":\n  golden: " + el + "\n  actual: " + al;
  }
  return "the files differ only in line endings or a final newline";
}

class Golden : public ::testing::TestWithParam<std::string> {};

TEST_P(Golden, OutputMatchesGoldenFiles) {
  const std::string name = GetParam();
  Diagnostics diags;
  auto graph = loadGraphFile(test::sourcePath("graphs/" + name + ".json"), diags);
  ASSERT_TRUE(graph) << name;
  auto result = compileGraph(*graph, defaultRegistry(), CompileOptions{}, diags);
  ASSERT_TRUE(result) << name << " does not compile";

  const std::string dir = goldenDir() + "/" + name;
  std::set<std::string> produced;
  for (const auto& f : result->files)
    if (isGolden(f.name)) produced.insert(f.name);

  if (test::updatingGoldens()) {
    fs::create_directories(dir);
    for (const auto& old : test::listFiles(dir))
      if (!produced.count(old) && !isWgslGolden(old)) fs::remove(dir + "/" + old);
    for (const auto& f : result->files)
      if (isGolden(f.name)) test::writeFile(dir + "/" + f.name, f.contents);
    std::cout << "[ golden   ] updated tests/golden/" << name << "/ (" << produced.size() << " files)\n";
    return;
  }

  const std::string hint = "\n(if the change is intended: WG_UPDATE_GOLDEN=1 ctest -R Golden, then review the diff; "
                           "see tests/golden/README.md)";
  for (const auto& f : result->files) {
    if (!isGolden(f.name)) continue;
    std::string path = dir + "/" + f.name;
    if (!fs::exists(path)) {
      ADD_FAILURE() << "no golden file tests/golden/" << name << "/" << f.name << hint;
      continue;
    }
    std::string expected = test::readFile(path);
    EXPECT_TRUE(expected == f.contents) << "tests/golden/" << name << "/" << f.name << " differs: "
                                         << firstDifference(expected, f.contents) << hint;
  }
  for (const auto& existing : test::listFiles(dir))
    EXPECT_TRUE(produced.count(existing) || isWgslGolden(existing))
        << "stale golden file tests/golden/" << name << "/" << existing << ": the compiler no longer writes it" << hint;
}

INSTANTIATE_TEST_SUITE_P(ExampleGraphs, Golden, ::testing::ValuesIn(graphNames()));

// The WGSL module, byte for byte: the only check of its text short of naga, Tint and Chromium
// (a local printed with the wrong type passes every other codegen test). A graph with a
// glsl_function node has no WGSL form (WG045) and no WGSL golden.
class GoldenWgsl : public ::testing::TestWithParam<std::string> {};

TEST_P(GoldenWgsl, ModuleMatchesGoldenFile) {
  const std::string name = GetParam();
  const std::string graphPath = test::sourcePath("graphs/" + name + ".json");
  const std::string golden = goldenDir() + "/" + name + "/" + name + ".wgsl";
  if (test::holdsGlslFunction(graphPath)) {
    EXPECT_FALSE(fs::exists(golden)) << "tests/golden/" << name << "/" << name << ".wgsl: the graph has no WGSL form";
    return;
  }
  Diagnostics diags;
  auto graph = loadGraphFile(graphPath, diags);
  ASSERT_TRUE(graph) << name;
  CompileOptions options;
  options.wgsl = true;
  auto result = compileGraph(*graph, defaultRegistry(), options, diags);
  ASSERT_TRUE(result) << name << " does not compile with the wgsl target";
  const OutputFile* module = nullptr;
  for (const auto& f : result->files)
    if (isWgslGolden(f.name)) module = &f;
  ASSERT_TRUE(module) << name << ": no .wgsl file";
  ASSERT_EQ(module->name, name + ".wgsl");
  if (test::updatingGoldens()) {
    test::writeFile(golden, module->contents);
    return;
  }
  ASSERT_TRUE(fs::exists(golden)) << "no golden file tests/golden/" << name << "/" << module->name
                                  << "\n(if the change is intended: WG_UPDATE_GOLDEN=1 ctest -R Golden)";
  const std::string expected = test::readFile(golden);
  EXPECT_TRUE(expected == module->contents) << "tests/golden/" << name << "/" << module->name << " differs: "
                                            << firstDifference(expected, module->contents)
                                            << "\n(if the change is intended: WG_UPDATE_GOLDEN=1 ctest -R Golden)";
}

INSTANTIATE_TEST_SUITE_P(ExampleGraphs, GoldenWgsl, ::testing::ValuesIn(graphNames()));

TEST(GoldenIndex, EveryGoldenFolderHasAGraph) {
  std::set<std::string> graphs;
  for (const auto& n : graphNames()) graphs.insert(n);
  std::error_code ec;
  for (fs::directory_iterator it(goldenDir(), ec), end; !ec && it != end; it.increment(ec)) {
    if (!it->is_directory()) continue;
    std::string name = it->path().filename().string();
    // Only folders of graph goldens (they hold a manifest); tests/golden/ is shared with
    // other suites (e.g. rendered images).
    if (test::listFiles(it->path().string(), ".manifest.json").empty()) continue;
    EXPECT_TRUE(graphs.count(name)) << "tests/golden/" << name << "/ has no graphs/" << name
                                    << ".json (remove the folder)";
  }
}

}  // namespace
}  // namespace wg
