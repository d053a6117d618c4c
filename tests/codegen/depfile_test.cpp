// The depfile (`compile --depfile`) is read by GNU Make and by Ninja, whose syntaxes differ:
// a path is escaped so that both read back the same path, and one that either would read
// differently is refused with an error (codegen/depfile.h). The round trip is tested with
// the real tools: each depfile is read by `make` (as an included makefile) and by `ninja`
// (as a build edge's depfile, then `ninja -t deps`), and both must see the very file.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>

#include "codegen/depfile.h"
#include "test_support.h"

namespace wg {
namespace {

namespace fs = std::filesystem;

bool haveTool(const std::string& tool) {
  std::string out;
  return test::runCommand("command -v " + tool + " > /dev/null 2>&1", &out) == 0;
}

// Paths a user may well have: every one is written so that both tools read it back.
const std::vector<std::string> kReadable = {"plain.json",  "a b.json",   "a#b.json",   "a$b.json",  "a:b.json",
                                            "a%b.json",    "a(b).json",  "a{b}.json",  "a[b].json", "a,b+c@d!e~f.json",
                                            "a\\b.json",   "a\\ b.json", "a\\\\ b.json", "caf\xc3\xa9.json", "a  b.json"};
// Paths one of them cannot read back: refused.
const std::vector<std::string> kUnreadable = {"a\nb.json", "a\tb.json", "a;b.json", "a|b.json",   "a=b.json",  "a\"b.json",
                                              "a'b.json",  "a*b.json",  "a?b.json", "a\\#b.json", "a\\",       "a\rb.json",
                                              "a<b.json",  "a&b.json",  "a`b.json"};

class DepfileRoundTrip : public ::testing::Test {
 protected:
  void SetUp() override { dir = test::makeTempDir("wg_depfile_"); }
  void TearDown() override { fs::remove_all(dir); }

  std::string depfileFor(const std::string& input) {
    Diagnostics diags;
    auto text = depfileText({{{"out"}, {input}}}, "dep.d", diags);
    EXPECT_TRUE(text) << input;
    return text.value_or("");
  }
  std::string dir;
};

TEST_F(DepfileRoundTrip, NinjaReadsBackEveryPath) {
  if (!haveTool("ninja")) GTEST_SKIP() << "no ninja";
  for (const auto& name : kReadable) {
    SCOPED_TRACE(name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    test::writeFile(dir + "/" + name, "x");
    test::writeFile(dir + "/build.ninja", "rule t\n  command = touch $out\n  depfile = dep.d\n  deps = gcc\nbuild out: t\n");
    test::writeFile(dir + "/dep.d", depfileFor(name));
    std::string out;
    ASSERT_EQ(test::runCommand("cd " + test::shellQuote(dir) + " && ninja 2>&1", &out), 0) << out;
    ASSERT_EQ(test::runCommand("cd " + test::shellQuote(dir) + " && ninja -t deps", &out), 0) << out;
    // `ninja -t deps`: "out: #deps 1, ..." then each dependency on its own line, indented,
    // then an empty line.
    auto lines = test::splitLines(out);
    ASSERT_GE(lines.size(), 2u) << out;
    EXPECT_NE(lines[0].find("#deps 1,"), std::string::npos) << out;
    EXPECT_EQ(lines[1], "    " + name);
  }
}

TEST_F(DepfileRoundTrip, MakeReadsBackEveryPath) {
  if (!haveTool("make")) GTEST_SKIP() << "no make";
  for (const auto& name : kReadable) {
    SCOPED_TRACE(name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    test::writeFile(dir + "/" + name, "x");
    test::writeFile(dir + "/Makefile", "out:\n\ttouch out\n-include dep.d\n");
    test::writeFile(dir + "/dep.d", depfileFor(name));
    test::writeFile(dir + "/out", "x");
    auto age = [&](const std::string& file, int seconds) {
      fs::last_write_time(dir + "/" + file, fs::file_time_type::clock::now() - std::chrono::seconds(seconds));
    };
    std::string out;
    // The input older than the output: up to date; newer: out of date. A path read as
    // another file would be missing ("No rule to make target", exit 2).
    age(name, 100);
    age("out", 10);
    EXPECT_EQ(test::runCommand("make -q -C " + test::shellQuote(dir) + " out 2>&1", &out), 0) << out;
    age(name, 1);
    EXPECT_EQ(test::runCommand("make -q -C " + test::shellQuote(dir) + " out 2>&1", &out), 1) << out;
  }
}

TEST(Depfile, PathsEitherToolWouldMisreadAreRefused) {
  for (const auto& name : kUnreadable) {
    SCOPED_TRACE(name);
    EXPECT_NE(depfilePathProblem(name), "");
    Diagnostics diags;
    EXPECT_FALSE(depfileText({{{"out"}, {"ok.json", name}}}, "dep.d", diags));
    ASSERT_TRUE(diags.hasErrors());
    EXPECT_EQ(diags.all().front().code, DiagCode::FileWrite);
    EXPECT_EQ(diags.all().front().where.file.str(), "dep.d");
  }
  for (const auto& name : kReadable) EXPECT_EQ(depfilePathProblem(name), "") << name;
}

TEST(Depfile, EscapesAsBothToolsRead) {
  Diagnostics diags;
  EXPECT_EQ(depfileText({{{"o u t"}, {"a b", "x#y", "p$q", "c:d", "e\\f", "g\\ h"}}}, "d", diags).value_or(""),
            "o\\ u\\ t: \\\n  a\\ b \\\n  x\\#y \\\n  p$$q \\\n  c\\:d \\\n  e\\f \\\n  g\\\\\\ h\n");
}

}  // namespace
}  // namespace wg
