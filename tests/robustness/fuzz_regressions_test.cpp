// Every crash or property failure the fuzzers found is saved in tests/fuzz/regressions/
// and replayed here through the same checks the fuzz targets make (tests/fuzz/
// fuzz_properties.h), in the ordinary (and the sanitizer) test run. The seed corpora (the
// example graphs and tests/bad) are replayed too, so a seed that starts failing is caught
// without running a fuzzer.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <string>
#include <vector>

#include "fuzz/edit_sequence.h"
#include "fuzz/formula_property.h"
#include "fuzz/function_file_property.h"
#include "fuzz/fuzz_properties.h"
#include "fuzz/imports_property.h"
#include "fuzz/texture_property.h"
#include "test_support.h"

namespace wg {
namespace {

std::vector<std::string> inputs() {
  std::vector<std::string> paths;
  for (const char* dir : {"tests/fuzz/regressions", "tests/bad", "graphs"})
    for (const auto& name : test::listFiles(test::sourcePath(dir)))
      if (name != "expected.txt" && name != "README.md") paths.push_back(std::string(dir) + "/" + name);
  return paths;
}

class FuzzInput : public ::testing::TestWithParam<std::string> {};

TEST_P(FuzzInput, LoaderAndPipelinePropertiesHold) {
  // Relative texture paths in the inputs resolve against the current folder, as in the
  // fuzzers (which run in their corpus folder): run from the input's own folder.
  std::string path = test::sourcePath(GetParam());
  std::string text = test::readFile(path);
  auto cwd = std::filesystem::current_path();
  std::filesystem::current_path(std::filesystem::path(path).parent_path());
  std::string loader = fuzz::loaderProperty(text);
  std::string pipeline = fuzz::pipelineProperty(text);
  std::filesystem::current_path(cwd);
  EXPECT_EQ(loader, "") << GetParam();
  EXPECT_EQ(pipeline, "") << GetParam();
}

std::string caseName(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Saved, FuzzInput, ::testing::ValuesIn(inputs()), caseName);

// The corpora of the texture and edit-sequence targets (tests/fuzz/corpus/), through their
// properties: small, and cheap to replay.
std::vector<std::string> corpus(const std::string& target) {
  std::vector<std::string> paths;
  for (const auto& name : test::listFiles(test::sourcePath("tests/fuzz/corpus/" + target)))
    paths.push_back("tests/fuzz/corpus/" + target + "/" + name);
  return paths;
}

TEST(FuzzCorpus, TexturePropertyHoldsForEveryKeptInput) {
  std::string scratch = test::makeTempDir("wg_texture_replay_");
  auto inputs = corpus("texture");
  EXPECT_FALSE(inputs.empty());
  for (const auto& path : inputs)
    EXPECT_EQ(fuzz::textureProperty(test::readFile(test::sourcePath(path)), scratch + "/run"), "") << path;
  std::filesystem::remove_all(scratch);
}

TEST(FuzzCorpus, ImportsPropertyHoldsForEveryKeptInput) {
  std::string scratch = test::makeTempDir("wg_imports_replay_");
  auto inputs = corpus("imports");
  EXPECT_GE(inputs.size(), 4u);
  for (const auto& path : inputs)
    EXPECT_EQ(fuzz::importsProperty(test::readFile(test::sourcePath(path)), scratch + "/run"), "") << path;
  std::filesystem::remove_all(scratch);
}

// The seeds reach both sides: a tree of files that compiles, and faulty trees reported.
TEST(FuzzCorpus, ImportsSeedsCompileAndFail) {
  std::string scratch = test::makeTempDir("wg_imports_sides_");
  auto outcome = [&](const std::string& seed) {
    auto files = fuzz::writeImportFiles(test::readFile(test::sourcePath("tests/fuzz/corpus/imports/" + seed)), scratch);
    Diagnostics diags;
    auto g = loadGraphFile(files[0], diags);
    std::optional<CompileResult> r;
    if (g) r = compileGraph(*g, defaultRegistry(), CompileOptions{}, diags);
    return r ? std::string("ok") : diags.sorted().empty() ? "?" : codeString(diags.sorted()[0].code);
  };
  EXPECT_EQ(outcome("two_instances"), "ok");
  EXPECT_EQ(outcome("nested"), "ok");
  EXPECT_EQ(outcome("cycle"), "WG072");
  EXPECT_EQ(outcome("interface_mismatch"), "WG074");
  std::filesystem::remove_all(scratch);
}

TEST(FuzzCorpus, FunctionFilePropertyHoldsForEveryKeptInput) {
  std::string scratch = test::makeTempDir("wg_function_file_replay_");
  auto inputs = corpus("function_file");
  EXPECT_GE(inputs.size(), 5u);
  for (const auto& path : inputs)
    EXPECT_EQ(fuzz::functionFileProperty(test::readFile(test::sourcePath(path)), scratch + "/run"), "") << path;
  std::filesystem::remove_all(scratch);
}

TEST(FuzzCorpus, EditSequencePropertyHoldsForEveryKeptInput) {
  auto inputs = corpus("edit_ops");
  EXPECT_FALSE(inputs.empty());
  for (const auto& path : inputs) EXPECT_EQ(fuzz::editSequenceProperty(test::readFile(test::sourcePath(path))), "") << path;
}

TEST(FuzzCorpus, FormulaPropertyHoldsForEveryKeptInput) {
  auto inputs = corpus("formula");
  EXPECT_FALSE(inputs.empty());
  for (const auto& path : inputs) EXPECT_EQ(fuzz::formulaProperty(test::readFile(test::sourcePath(path))), "") << path;
}

// The property itself reaches both of its sides: well-formed formulas compile, and faulty
// ones (escaped characters before the fault included) are placed on the formula's string.
TEST(FuzzCorpus, FormulaPropertySeesBothOutcomes) {
  for (const char* formula : {"mix(c, vec3(1.0), a)", "d.x", "\"\\\t\u00e9 + zz", "a +", "c + b", "((a)"})
    EXPECT_EQ(fuzz::formulaProperty(formula), "") << formula;
  Diagnostics diags;
  auto graph = parseGraph(fuzz::formulaGraph("\ta +\t nosuch", Type::Invalid), "fuzz.json", diags);
  ASSERT_TRUE(graph);
  EXPECT_FALSE(buildProgram(*graph, defaultRegistry(), diags));
  ASSERT_TRUE(diags.hasErrors());
  // `nosuch` at decoded offset 6, after \ta +\t written in 8 bytes; the string starts at column 17.
  EXPECT_EQ(diags.sorted().front().where.col, 17 + 8);
}

}  // namespace
}  // namespace wg
