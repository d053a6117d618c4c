// Hostile graph files, second round (docs/robustness.md): work that must stay near-linear
// in the file (suggestions, diagnostics), output formats that must not open the graph file
// again, every cycle named, and literals that keep their sign.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <sys/stat.h>

#include "codegen/compile.h"
#include "core/graph_io.h"
#include "core/suggest.h"
#include "nodes/registry.h"
#include "test_support.h"

namespace wg {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

using test::secondsSince;

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Loads and resolves `text`; returns the diagnostics and how long it took.
Diagnostics check(const std::string& text, double* seconds = nullptr) {
  Diagnostics diags;
  auto t0 = Clock::now();
  if (auto graph = parseGraph(text, "hostile.json", diags)) buildProgram(*graph, defaultRegistry(), diags);
  if (seconds) *seconds = secondsSince(t0);
  return diags;
}

size_t countCode(const Diagnostics& diags, DiagCode code) {
  size_t n = 0;
  for (const auto& d : diags.all()) n += d.code == code;
  return n;
}

std::string allMessages(const Diagnostics& diags) {
  std::string s;
  for (const auto& d : diags.sorted()) s += formatText(d) + "\n";
  return s;
}

// Before the fix every bad reference compared itself with every name: 30,000 dangling
// references took about a minute. The bound here is generous for a sanitizer build on a
// busy machine; the fixed code takes well under a second in a release build.
constexpr double kLinearSeconds = 15;

TEST(HostileInput, DanglingReferencesCostLinearTime) {
  const int n = 30000;
  std::string nodes;
  for (int i = 0; i < n; ++i)
    nodes += std::string(i ? ",\n" : "") + "{\"id\": \"node_" + std::to_string(i) +
             "\", \"type\": \"sin\", \"inputs\": {\"x\": \"nade_" + std::to_string(i) + ".out\"}}";
  double seconds = 0;
  Diagnostics diags = check(test::graphJson(nodes, "\"fragment\": {\"alpha\": \"node_0.out\"}"), &seconds);
  EXPECT_LT(seconds, kLinearSeconds);
  EXPECT_EQ(diags.errorCount(), static_cast<size_t>(n));  // every one counted, shown or not
  // Suggestions are made, up to their cap, and then stop.
  std::string text = allMessages(diags);
  EXPECT_NE(text.find("no node with id 'nade_0' (did you mean 'node_0'?)"), std::string::npos);
  EXPECT_LE(count(text, "did you mean"), NameSuggester::kMaxSuggestions);
}

TEST(HostileInput, UnknownParametersCostLinearTime) {
  const int n = 20000;
  std::string nodes, parameters;
  for (int i = 0; i < n; ++i) {
    nodes += std::string(i ? ",\n" : "") + "{\"id\": \"n" + std::to_string(i) +
             "\", \"type\": \"sin\", \"inputs\": {\"x\": \"$q" + std::to_string(i) + "\"}}";
    parameters += std::string(i ? ",\n" : "") + "\"p" + std::to_string(i) + "\": {\"type\": \"float\", \"default\": 0}";
  }
  double seconds = 0;
  Diagnostics diags = check(test::graphJson(nodes, "\"fragment\": {\"alpha\": \"n0.out\"}", parameters), &seconds);
  EXPECT_LT(seconds, kLinearSeconds);
  EXPECT_EQ(diags.errorCount(), static_cast<size_t>(n));
}

TEST(HostileInput, APresetOfUndeclaredParametersCostsLinearTime) {
  const int n = 20000;
  std::string parameters, values;
  for (int i = 0; i < n; ++i) {
    parameters += std::string(i ? ",\n" : "") + "\"p" + std::to_string(i) + "\": {\"type\": \"float\", \"default\": 0}";
    values += std::string(i ? ",\n" : "") + "\"q" + std::to_string(i) + "\": 1";
  }
  std::string text = "{\"version\": 1, \"name\": \"t\", \"parameters\": {" + parameters +
                     "}, \"presets\": {\"calm\": {" + values +
                     "}}, \"nodes\": [{\"id\": \"c\", \"type\": \"sin\", \"inputs\": {\"x\": 1}}], "
                     "\"outputs\": {\"fragment\": {\"alpha\": \"c.out\"}}}";
  double seconds = 0;
  Diagnostics diags = check(text, &seconds);
  EXPECT_LT(seconds, kLinearSeconds);
  EXPECT_EQ(countCode(diags, DiagCode::UnknownParameter) + (diags.errorCount() - diags.all().size()),
            static_cast<size_t>(n));
}

TEST(HostileInput, LongUnknownTypeNamesAreNotComparedWithShortOnes) {
  const int n = 4000;
  std::string nodes;
  for (int i = 0; i < n; ++i)
    nodes += std::string(i ? ",\n" : "") + "{\"id\": \"n" + std::to_string(i) + "\", \"type\": \"" +
             std::string(4000, 'a') + std::to_string(i) + "\"}";
  double seconds = 0;
  Diagnostics diags = check(test::graphJson(nodes, "\"fragment\": {\"alpha\": \"n0.out\"}"), &seconds);
  EXPECT_LT(seconds, kLinearSeconds);
  EXPECT_GE(diags.errorCount(), static_cast<size_t>(n));
}

TEST(HostileInput, SuggestionsStillFindTheNearestName) {
  NameSuggester names({"fresnel", "fbm", "gerstner_waves", "fresnel_schlick"});
  EXPECT_EQ(names.closest("frensel"), "fresnel");
  EXPECT_EQ(names.closest("fbn"), "fbm");
  EXPECT_EQ(names.closest("gerstner_wave"), "gerstner_waves");
  EXPECT_EQ(names.closest("completely_different"), "");
  // Ties go to the earlier name in the given list, as before.
  EXPECT_EQ(NameSuggester({"ab", "ba"}).closest("aa"), "ab");
  EXPECT_EQ(NameSuggester({"ba", "ab"}).closest("aa"), "ba");
}

// 5,000 duplicate keys: at most kMaxPerFile diagnostics per file, then one note, in the
// text, JSON and SARIF output alike.
TEST(HostileInput, DiagnosticsAreCappedPerFileInEveryFormat) {
  const size_t n = 5000;
  std::string keys;
  for (size_t i = 0; i < n; ++i) keys += ", \"x\": 1";
  std::string nodes = "{\"id\": \"c\", \"type\": \"sin\", \"inputs\": {\"x\": 1" + keys + "}}";
  std::string dir = test::makeTempDir("wg_cap_");
  test::writeFile(dir + "/dup.json", test::graphJson(nodes, "\"fragment\": {\"alpha\": \"c.out\"}"));
  const std::string wg = test::shellQuote(test::watergraphBinary()) + " validate " + dir + "/dup.json";
  std::string out, err;
  EXPECT_EQ(test::runCommandSplit(wg, &out, &err), 1);
  auto lines = test::splitLines(err);  // each duplicate key is an error line and a note line
  ASSERT_EQ(count(err, "error: [WG003]"), Diagnostics::kMaxPerFile) << err.substr(0, 2000);
  ASSERT_EQ(lines.size(), 2 * Diagnostics::kMaxPerFile + 1) << err.substr(0, 2000);
  EXPECT_NE(lines.back().find("note: [WG036] " + std::to_string(n - Diagnostics::kMaxPerFile) + " more diagnostics"),
            std::string::npos)
      << lines.back();
  EXPECT_EQ(test::runCommandSplit(wg + " --diagnostics-format json", &out, &err), 1);
  auto json = nlohmann::json::parse(out);
  ASSERT_EQ(json["diagnostics"].size(), Diagnostics::kMaxPerFile + 1);
  EXPECT_EQ(json["diagnostics"].back()["code"], "WG036");
  EXPECT_EQ(test::runCommandSplit(wg + " --diagnostics-format sarif", &out, &err), 1);
  auto sarif = nlohmann::json::parse(out);
  ASSERT_EQ(sarif["runs"][0]["results"].size(), Diagnostics::kMaxPerFile + 1);
  EXPECT_EQ(sarif["runs"][0]["results"].back()["ruleId"], "WG036");
  fs::remove_all(dir);
}

// SARIF needs each line's text to count UTF-16 columns: it uses the snapshot that was
// loaded. Opening the graph file a second time blocked forever on a FIFO.
TEST(HostileInput, SarifNeverOpensTheGraphFileAgain) {
  std::string dir = test::makeTempDir("wg_sarif_fifo_");
  std::string fifo = dir + "/g.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  // "é" before the fault: the unknown key's column in UTF-16 units (22) is not its byte column (23).
  test::writeFile(dir + "/src.json",
                  "{\"description\": \"é\", \"zz\": 1, \"version\": 1, \"name\": \"t\", \"nodes\": [], \"outputs\": {}}\n");
  std::string writer = "(timeout 60 cat " + dir + "/src.json > " + fifo + " &) ; ";
  std::string out, err;
  int code = test::runCommandSplit(writer + "timeout 20 " + test::shellQuote(test::watergraphBinary()) +
                                       " validate --diagnostics-format sarif " + fifo,
                                   &out, &err);
  ASSERT_EQ(code, 1) << out << err;  // 124 when it hung
  auto sarif = nlohmann::json::parse(out);
  bool found = false;
  for (const auto& r : sarif["runs"][0]["results"])
    if (r["ruleId"] == "WG006") {
      found = true;
      EXPECT_EQ(r["locations"][0]["physicalLocation"]["region"]["startColumn"], 22) << r.dump();
    }
  EXPECT_TRUE(found) << out;
  fs::remove_all(dir);
}

TEST(HostileInput, DisjointCyclesAreEachReported) {
  // a <-> b and c -> d -> e -> c, and f behind the first cycle (not a cycle of its own).
  std::string nodes =
      "{\"id\": \"a\", \"type\": \"sin\", \"inputs\": {\"x\": \"b.out\"}},"
      "{\"id\": \"b\", \"type\": \"sin\", \"inputs\": {\"x\": \"a.out\"}},"
      "{\"id\": \"f\", \"type\": \"sin\", \"inputs\": {\"x\": \"a.out\"}},"
      "{\"id\": \"c\", \"type\": \"sin\", \"inputs\": {\"x\": \"e.out\"}},"
      "{\"id\": \"d\", \"type\": \"sin\", \"inputs\": {\"x\": \"c.out\"}},"
      "{\"id\": \"e\", \"type\": \"sin\", \"inputs\": {\"x\": \"d.out\"}}";
  Diagnostics diags = check(test::graphJson(nodes, "\"fragment\": {\"alpha\": \"f.out\"}"));
  ASSERT_EQ(countCode(diags, DiagCode::Cycle), 2u) << allMessages(diags);
  std::string text = allMessages(diags);
  EXPECT_NE(text.find("'a' -> 'b' -> 'a'"), std::string::npos) << text;
  EXPECT_NE(text.find("'c' -> 'd' -> 'e' -> 'c'"), std::string::npos) << text;
}

// A cycle through 10,000 nodes is one line naming its first and last 8 steps (it listed
// every id: a 1.8 MB line for 150,000).
TEST(HostileInput, ALongCycleIsNamedByItsEnds) {
  std::string nodes;
  const int n = 10000;
  for (int i = 0; i < n; ++i)
    nodes += std::string(i ? "," : "") + "{\"id\": \"n" + std::to_string(i) + "\", \"type\": \"sin\", \"inputs\": {\"x\": \"n" +
             std::to_string((i + 1) % n) + ".out\"}}";
  Diagnostics diags = check(test::graphJson(nodes, "\"fragment\": {\"alpha\": \"n0.out\"}"));
  ASSERT_EQ(countCode(diags, DiagCode::Cycle), 1u);
  std::string text = allMessages(diags);
  EXPECT_LT(text.size(), 1000u) << text.substr(0, 2000);
  EXPECT_NE(text.find("... (9984 more nodes) -> "), std::string::npos) << text;
  EXPECT_NE(text.find("'n0' -> 'n9999' -> 'n9998'"), std::string::npos) << text;
}

// 1 / -0.0 is -inf: the literal keeps its sign in every target's GLSL, alone and in a vector.
TEST(HostileInput, NegativeZeroLiteralsKeepTheirSign) {
  std::string nodes =
      "{\"id\": \"q\", \"type\": \"div\", \"inputs\": {\"a\": 1, \"b\": -0.0}},"
      "{\"id\": \"v\", \"type\": \"div\", \"inputs\": {\"a\": [1, 1, 1], \"b\": [0.0, -0.0, 0.0]}},"
      "{\"id\": \"s\", \"type\": \"dot\", \"inputs\": {\"a\": \"v.out\", \"b\": \"v.out\"}},"
      "{\"id\": \"m\", \"type\": \"add\", \"inputs\": {\"a\": \"q.out\", \"b\": \"s.out\"}}";
  Diagnostics diags;
  auto graph = parseGraph(test::graphJson(nodes, "\"fragment\": {\"alpha\": \"m.out\"}"), "negzero.json", diags);
  ASSERT_TRUE(graph) << allMessages(diags);
  auto result = compileGraph(*graph, defaultRegistry(), CompileOptions{}, diags);
  ASSERT_TRUE(result) << allMessages(diags);
  int fragments = 0;
  for (const auto& f : result->files) {
    if (f.name.size() < 5 || f.name.substr(f.name.size() - 5) != ".frag") continue;
    ++fragments;
    EXPECT_NE(f.contents.find("-0.0)"), std::string::npos) << f.name << "\n" << f.contents;
    EXPECT_NE(f.contents.find("vec3(0.0, -0.0, 0.0)"), std::string::npos) << f.name << "\n" << f.contents;
  }
  EXPECT_EQ(fragments, 3);
}

}  // namespace
}  // namespace wg
