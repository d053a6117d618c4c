// docs/nodes.md is generated from the node registry (`watergraph nodes --markdown`) and
// docs/diagnostics.md from the diagnostic catalogue (`watergraph codes --markdown`), both
// checked in; this keeps them from drifting apart. To refresh them (and the schema):
//   cmake --build build --target docs
#include <gtest/gtest.h>

#include <filesystem>

#include "core/diagnostic.h"
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

TEST(Docs, DiagnosticTableMatchesTheCatalogue) {
  std::string path = test::sourcePath("docs/diagnostics.md");
  ASSERT_TRUE(std::filesystem::exists(path)) << "docs/diagnostics.md is missing; generate it with: cmake --build build --target docs";
  std::string out, err;
  int exit = test::runCommandSplit(test::shellQuote(test::watergraphBinary()) + " codes --markdown", &out, &err);
  ASSERT_EQ(exit, 0) << err;
  // Every code of the catalogue has a row, with a meaning and an example.
  for (const auto& info : diagnosticCatalogue()) {
    SCOPED_TRACE(codeString(info.code));
    EXPECT_FALSE(info.summary.empty());
    EXPECT_FALSE(info.example.empty());
    EXPECT_NE(out.find("| " + codeString(info.code) + " | " + std::string(info.enumerator) + " | "), std::string::npos);
  }
  EXPECT_TRUE(out == test::readFile(path))
      << "docs/diagnostics.md is out of date; regenerate it with: cmake --build build --target docs";
}

}  // namespace
}  // namespace wg
