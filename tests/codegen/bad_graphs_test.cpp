// The bad-graph corpus (tests/bad/): every file must fail, and the first diagnostic (in
// printing order: by line, then column) must carry the code and position that
// tests/bad/expected.txt gives for it. Positions were worked out by hand from where the
// error is in each file (docs/graph-format.md: a value's first character, a key's opening
// quote, a missing field at the enclosing '{'), not copied from the tool's output.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "codegen/compile.h"
#include "core/diagnostic.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg {
namespace {

struct BadCase {
  std::string file;  // name in tests/bad/
  std::string code;  // "WG029"
  int line = 0;
  int col = 0;
  std::string in;  // the file the diagnostic lies in, relative to tests/bad ("": the bad graph)
};

void PrintTo(const BadCase& c, std::ostream* os) {
  *os << c.file << " " << c.code << " " << c.line << ":" << c.col;
}

std::string badDir() { return test::sourcePath("tests/bad"); }

std::vector<BadCase> loadExpected() {
  std::vector<BadCase> cases;
  std::ifstream in(badDir() + "/expected.txt");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ss(line);
    BadCase c;
    std::string pos;
    std::string in;
    ss >> c.file >> c.code >> pos >> in;
    if (in.size() > 1 && in[0] == '@') c.in = in.substr(1);
    auto colon = pos.find(':');
    if (colon == std::string::npos) continue;  // reported by the index test
    c.line = std::stoi(pos.substr(0, colon));
    c.col = std::stoi(pos.substr(colon + 1));
    cases.push_back(c);
  }
  return cases;
}

// Catalogue codes below 40 that no bad graph's first diagnostic can be: WG036, the note
// after a file's first 1,000 diagnostics (tests/robustness/hostile_input_test.cpp).
const std::set<int> kUnreachableFromGraphs = {36};

class BadGraph : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadGraph, FirstDiagnosticHasExpectedCodeAndPosition) {
  const BadCase& c = GetParam();
  std::string path = badDir() + "/" + c.file;
  Diagnostics diags;
  auto graph = loadGraphFile(path, diags);
  std::optional<CompileResult> result;
  if (graph) {
    CompileOptions options;
    result = compileGraph(*graph, defaultRegistry(), options, diags);
  }
  EXPECT_FALSE(result.has_value()) << c.file << " compiled";
  ASSERT_TRUE(diags.hasErrors()) << c.file << " produced no error";
  auto sorted = diags.sorted();
  const Diagnostic& first = sorted.front();
  std::string all;
  for (const auto& d : sorted) all += "  " + formatText(d) + "\n";
  EXPECT_EQ(codeString(first.code), c.code) << all;
  EXPECT_EQ(first.where.line, c.line) << all;
  EXPECT_EQ(first.where.col, c.col) << all;
  EXPECT_EQ(first.where.file, c.in.empty() ? path : badDir() + "/" + c.in) << all;
  // A fault in an imported file names the import (or instance) that reached it.
  if (!c.in.empty()) EXPECT_FALSE(first.locatedNotes.empty()) << all;
  EXPECT_EQ(first.severity, Severity::Error) << all;
}

std::string caseName(const ::testing::TestParamInfo<BadCase>& info) {
  std::string name = info.param.file;
  if (name.size() > 5 && name.compare(name.size() - 5, 5, ".json") == 0) name.resize(name.size() - 5);
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadGraph, ::testing::ValuesIn(loadExpected()), caseName);

TEST(BadGraphIndex, EveryLineIsWellFormed) {
  std::ifstream in(badDir() + "/expected.txt");
  ASSERT_TRUE(in) << "tests/bad/expected.txt is missing";
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ss(line);
    std::string file, code, pos, in, extra;
    ss >> file >> code >> pos >> in >> extra;
    EXPECT_TRUE(in.empty() || (in[0] == '@' && test::readFile(badDir() + "/" + in.substr(1)).size() > 0))
        << "line " << n << ": " << line;
    EXPECT_TRUE(extra.empty()) << "line " << n << ": " << line;
    EXPECT_NE(pos.find(':'), std::string::npos) << "line " << n << ": " << line;
    ASSERT_GE(file.size(), 6u) << "line " << n;
    // Files are named <code>_<what>.json.
    EXPECT_EQ(file.substr(0, 6), code + "_") << "line " << n << ": " << line;
  }
}

TEST(BadGraphIndex, EveryFileIsListedAndEveryEntryExists) {
  std::set<std::string> listed;
  for (const auto& c : loadExpected()) {
    EXPECT_TRUE(listed.insert(c.file).second) << c.file << " is listed twice";
  }
  std::set<std::string> present;
  for (const auto& name : test::listFiles(badDir(), ".json")) present.insert(name);
  for (const auto& f : present) EXPECT_TRUE(listed.count(f)) << "tests/bad/" << f << " is not in expected.txt";
  for (const auto& f : listed) EXPECT_TRUE(present.count(f)) << "expected.txt lists missing file " << f;
  // Nothing else lives there (a stray non-JSON file would be silently untested).
  for (const auto& name : test::listFiles(badDir()))
    EXPECT_TRUE(present.count(name) || name == "expected.txt") << "unexpected file tests/bad/" << name;
}

TEST(BadGraphIndex, EveryCodeAGraphCanTriggerHasAFile) {
  std::set<std::string> covered;
  for (const auto& c : loadExpected()) covered.insert(c.code);
  for (const auto& info : diagnosticCatalogue()) {
    int number = static_cast<int>(info.code);
    // 04x: generated code (not reachable from a valid graph); 05x: files and the command
    // line (tests/cli covers WG050 and WG051); 06x: probe cases files. 07x (imports) are
    // graphs' faults again.
    if ((number >= 40 && number < 70) || kUnreachableFromGraphs.count(number)) continue;
    EXPECT_TRUE(covered.count(codeString(info.code)))
        << codeString(info.code) << " (" << info.enumerator << ") has no bad graph in tests/bad/";
  }
}

}  // namespace
}  // namespace wg
