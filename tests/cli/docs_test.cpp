// docs/nodes.md is generated from the node registry (`watergraph nodes --markdown`) and
// checked in; this keeps the two from drifting apart. To refresh it (and the schema):
//   cmake --build build --target docs
#include <gtest/gtest.h>

#include <filesystem>

#include "test_support.h"

namespace wg {
namespace {

TEST(Docs, NodeReferenceMatchesTheRegistry) {
  std::string path = test::sourcePath("docs/nodes.md");
  ASSERT_TRUE(std::filesystem::exists(path)) << "docs/nodes.md is missing; generate it with: cmake --build build --target docs";
  std::string out, err;
  int exit = test::runCommandSplit(test::shellQuote(test::watergraphBinary()) + " nodes --markdown", &out, &err);
  ASSERT_EQ(exit, 0) << err;
  EXPECT_FALSE(out.empty());
  EXPECT_TRUE(out == test::readFile(path))
      << "docs/nodes.md is out of date; regenerate it with: cmake --build build --target docs";
}

}  // namespace
}  // namespace wg
