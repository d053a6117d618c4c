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

#include "fuzz/fuzz_properties.h"
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

}  // namespace
}  // namespace wg
