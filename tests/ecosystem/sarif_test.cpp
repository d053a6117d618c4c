// --diagnostics-format sarif: a SARIF 2.1.0 log that code-scanning tools (GitHub, GitLab,
// VS Code's SARIF viewer) read: rules from the diagnostic catalogue, one result per
// diagnostic with its rule, level, message and file position.
#include <gtest/gtest.h>

#include <regex>
#include <set>

#include <nlohmann/json.hpp>

#include "core/diagnostic.h"
#include "eco_support.h"

namespace wg {
namespace {

using test::shellQuote;

// A bad graph on one line: the error (an unknown node type, WG020) sits after a
// description with multi-byte UTF-8, so byte and UTF-16 columns differ.
const char* kOneLineBadGraph =
    "{\"version\": 1, \"name\": \"g\", \"description\": \"\xC3\xA9t\xC3\xA9 \xF0\x9F\x8C\x8A\", "
    "\"nodes\": [{\"id\": \"a\", \"type\": \"nope\"}], \"outputs\": {\"fragment\": {\"alpha\": 1}}}\n";

nlohmann::json parseSarif(const std::string& out) {
  nlohmann::json j = nlohmann::json::parse(out);  // the whole of stdout is one log
  EXPECT_EQ(j["version"], "2.1.0");
  EXPECT_TRUE(j["$schema"].get<std::string>().find("sarif-2.1.0") != std::string::npos);
  EXPECT_EQ(j["runs"].size(), 1u);
  return j;
}

TEST(Sarif, DriverListsTheDiagnosticCatalogueAsRules) {
  auto r = eco::wgRun("validate " + shellQuote(test::sourcePath("graphs/lake.json")) + " --diagnostics-format sarif");
  ASSERT_EQ(r.exit, 0) << r.err;
  auto log = parseSarif(r.out);
  const auto& driver = log["runs"][0]["tool"]["driver"];
  EXPECT_EQ(driver["name"], "watergraph");
  const auto& rules = driver["rules"];
  ASSERT_EQ(rules.size(), diagnosticCatalogue().size());
  for (size_t i = 0; i < rules.size(); ++i) {
    const auto& info = diagnosticCatalogue()[i];
    EXPECT_EQ(rules[i]["id"], codeString(info.code));
    EXPECT_EQ(rules[i]["name"], std::string(info.enumerator));
    EXPECT_EQ(rules[i]["shortDescription"]["text"], std::string(info.summary));
  }
  EXPECT_TRUE(log["runs"][0]["results"].empty());
}

TEST(Sarif, ResultsCarryRuleLevelMessageAndPosition) {
  std::string bad = test::sourcePath("tests/ecosystem/schema_bad/unknown_option_value.json");
  std::string lake = test::sourcePath("graphs/lake.json");
  auto text = eco::wgRun("validate " + shellQuote(bad));
  auto r = eco::wgRun("--diagnostics-format sarif validate " + shellQuote(lake) + " " + shellQuote(bad));
  EXPECT_EQ(r.exit, 1);
  auto log = parseSarif(r.out);
  const auto& run = log["runs"][0];
  const auto& results = run["results"];
  ASSERT_EQ(results.size(), 1u) << r.out;
  const auto& res = results[0];
  EXPECT_EQ(res["ruleId"], "WG030");
  EXPECT_EQ(res["level"], "error");
  EXPECT_FALSE(res["message"]["text"].get<std::string>().empty());
  // ruleIndex points at the rule with the same id.
  size_t idx = res["ruleIndex"];
  EXPECT_EQ(run["tool"]["driver"]["rules"][idx]["id"], "WG030");
  const auto& phys = res["locations"][0]["physicalLocation"];
  EXPECT_EQ(phys["artifactLocation"]["uri"], "file://" + bad);
  // The same position as the text format's file:line:col (ASCII file: bytes = UTF-16 units).
  std::smatch m;
  ASSERT_TRUE(std::regex_search(text.err, m, std::regex(":(\\d+):(\\d+): error: \\[WG030\\]"))) << text.err;
  EXPECT_EQ(phys["region"]["startLine"], std::stoi(m[1]));
  EXPECT_EQ(phys["region"]["startColumn"], std::stoi(m[2]));
  EXPECT_EQ(res["locations"][0]["logicalLocations"][0]["name"], "f");
}

TEST(Sarif, RelativePathsStayRelativeAndColumnsAreUtf16) {
  eco::TempDir tmp;
  test::writeFile(tmp / "one line.json", kOneLineBadGraph);
  auto text = eco::sh("cd " + shellQuote(tmp.path()) + " && " + shellQuote(test::watergraphBinary()) +
                      " validate 'one line.json'");
  auto r = eco::sh("cd " + shellQuote(tmp.path()) + " && " + shellQuote(test::watergraphBinary()) +
                   " validate 'one line.json' --diagnostics-format sarif");
  EXPECT_EQ(r.exit, 1);
  auto log = parseSarif(r.out);
  ASSERT_EQ(log["runs"][0]["results"].size(), 1u);
  const auto& res = log["runs"][0]["results"][0];
  EXPECT_EQ(res["ruleId"], "WG020");
  const auto& phys = res["locations"][0]["physicalLocation"];
  EXPECT_EQ(phys["artifactLocation"]["uri"], "one%20line.json");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(text.err, m, std::regex(":1:(\\d+): error: \\[WG020\\]"))) << text.err;
  int byteColumn = std::stoi(m[1]);
  // "été 🌊" is 10 bytes but 6 UTF-16 code units (é: 2 bytes -> 1 unit; 🌊: 4 bytes -> 2).
  EXPECT_EQ(phys["region"]["startLine"], 1);
  EXPECT_EQ(phys["region"]["startColumn"], byteColumn - 4);
  EXPECT_EQ(log["runs"][0]["columnKind"], "utf16CodeUnits");
}

TEST(Sarif, CompileKeepsStdoutForTheLog) {
  eco::TempDir tmp;
  auto r = eco::wgRun("compile " + shellQuote(test::sourcePath("graphs/lake.json")) + " -o " + shellQuote(tmp / "out") +
                      " --summary --verbose --diagnostics-format sarif");
  EXPECT_EQ(r.exit, 0) << r.err;
  auto log = parseSarif(r.out);  // the summary table went to stderr
  EXPECT_TRUE(log["runs"][0]["results"].empty());
  EXPECT_NE(r.err.find("lake"), std::string::npos) << r.err;
}

TEST(Sarif, JsonFormatIsUnchanged) {
  std::string bad = test::sourcePath("tests/ecosystem/schema_bad/unknown_option_value.json");
  auto r = eco::wgRun("validate " + shellQuote(bad) + " --diagnostics-format json");
  EXPECT_EQ(r.exit, 1);
  auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["diagnostics"].size(), 1u);
  EXPECT_EQ(j["diagnostics"][0]["code"], "WG030");
  EXPECT_GT(j["diagnostics"][0]["line"].get<int>(), 0);
}

// A fault inside a subgraph: the result lies in the subgraph's file, and the instance that
// reached it is a related location (and a note line in the message text).
TEST(Sarif, AFaultInsideASubgraphNamesItsInstanceAsARelatedLocation) {
  std::string bad = test::sourcePath("tests/bad/WG025_inside_a_subgraph.json");
  auto r = eco::wgRun("validate " + shellQuote(bad) + " --diagnostics-format sarif");
  EXPECT_EQ(r.exit, 1);
  auto log = parseSarif(r.out);
  const auto& result = log["runs"][0]["results"][0];
  EXPECT_EQ(result["ruleId"], "WG025");
  std::string uri = result["locations"][0]["physicalLocation"]["artifactLocation"]["uri"];
  EXPECT_TRUE(uri.ends_with("tests/bad/imports/broken_reference.json")) << uri;
  ASSERT_EQ(result["relatedLocations"].size(), 1u) << result.dump(2);
  const auto& related = result["relatedLocations"][0];
  std::string relatedUri = related["physicalLocation"]["artifactLocation"]["uri"];
  EXPECT_TRUE(relatedUri.ends_with("tests/bad/WG025_inside_a_subgraph.json")) << relatedUri;
  EXPECT_EQ(related["physicalLocation"]["region"]["startLine"], 5);
  EXPECT_EQ(related["physicalLocation"]["region"]["startColumn"], 13);
  EXPECT_EQ(related["message"]["text"], "in instance 'b' of 'imports/broken_reference.json'");
  std::string text = result["message"]["text"];
  EXPECT_NE(text.find("\nnote: in instance 'b'"), std::string::npos) << text;
}

}  // namespace
}  // namespace wg
