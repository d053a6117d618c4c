// --preset on compile, validate and render's shared compile path: the preset's values
// become parameter defaults (static ones fold), the manifest records it, and a preset the
// graph does not define is one WG052 line, exit 2, nothing written.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "test_support.h"

namespace wg {
namespace {

namespace fs = std::filesystem;

using test::CmdResult;
CmdResult wg(const std::string& args) { return test::runWatergraph(args); }

std::string topdown() { return test::shellQuote(test::sourcePath("graphs/topdown.json")); }

TEST(CliPreset, PlainCompilesFoamRipplesAndVariationOut) {
  std::string dir = test::makeTempDir("wg_preset_");
  CmdResult full = wg("compile " + topdown() + " -o " + dir + "/full --target glsl330");
  CmdResult plain = wg("compile " + topdown() + " -o " + dir + "/plain --target glsl330 --preset plain");
  ASSERT_EQ(full.exit, 0) << full.err;
  ASSERT_EQ(plain.exit, 0) << plain.err;
  std::string a = test::readFile(dir + "/full/topdown.glsl330.frag");
  std::string b = test::readFile(dir + "/plain/topdown.glsl330.frag");
  for (const char* fn : {"wg_crest_foam", "wg_ripple_normals", "wg_color_variation"}) {
    EXPECT_NE(a.find(fn), std::string::npos) << fn;
    EXPECT_EQ(b.find(fn), std::string::npos) << fn << " is compiled out by --preset plain";
  }
  auto manifest = nlohmann::json::parse(test::readFile(dir + "/plain/topdown.manifest.json"));
  EXPECT_EQ(manifest.value("preset", ""), "plain");
  EXPECT_FALSE(nlohmann::json::parse(test::readFile(dir + "/full/topdown.manifest.json")).contains("preset"));
  fs::remove_all(dir);
}

TEST(CliPreset, WeatherPresetsChangeTheFoldedConstants) {
  std::string dir = test::makeTempDir("wg_preset_");
  std::string calm, choppy;
  ASSERT_EQ(wg("compile " + topdown() + " -o " + dir + "/calm --target glsl330 --preset calm").exit, 0);
  ASSERT_EQ(wg("compile " + topdown() + " -o " + dir + "/choppy --target glsl330 --preset choppy").exit, 0);
  calm = test::readFile(dir + "/calm/topdown.glsl330.frag");
  choppy = test::readFile(dir + "/choppy/topdown.glsl330.frag");
  EXPECT_NE(calm, choppy);
  EXPECT_NE(calm.find("0.9"), std::string::npos) << "calm's foam threshold is a constant";
  EXPECT_EQ(calm.find("p_foam_threshold"), std::string::npos) << "static: never a uniform";
  fs::remove_all(dir);
}

TEST(CliPreset, UnknownPresetIsWG052AndWritesNothing) {
  std::string dir = test::makeTempDir("wg_preset_");
  CmdResult r = wg("compile " + topdown() + " -o " + dir + "/out --preset stormy");
  EXPECT_EQ(r.exit, 2);
  EXPECT_NE(r.err.find("error: [WG052] graph 'topdown' has no preset 'stormy'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("its presets: calm, moderate, choppy, plain, debug"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out/topdown.manifest.json"));
  CmdResult v = wg("validate " + topdown() + " --preset clam");
  EXPECT_EQ(v.exit, 2);
  EXPECT_NE(v.err.find("did you mean 'calm'?"), std::string::npos) << v.err;
  fs::remove_all(dir);
}

// A preset that gives an expression node a formula calling an unknown function, or
// inputs of another type, is found by a plain validate and compile (the preset not
// applied): those values are checked by building the graph with the preset, which each
// compile does for every preset that sets node options. The error names the preset and
// points at its member.
TEST(CliPreset, APresetsExpressionIsCheckedWithoutApplyingIt) {
  std::string dir = test::makeTempDir("wg_preset_expr_");
  const std::string graph = R"json({"version": 1, "name": "p",
  "nodes": [{"id": "ex", "type": "expression", "options": {"inputs": {"a": "float"}, "formula": "a * 2.0"}, "inputs": {"a": 0.5}}],
  "outputs": {"fragment": {"alpha": "ex.out"}},
  "presets": {"PRESET": {"ex.MEMBER": VALUE}}})json";
  auto withPreset = [&](const std::string& member, const std::string& value) {
    std::string g = graph;
    g.replace(g.find("PRESET"), 6, "worn");
    g.replace(g.find("MEMBER"), 6, member);
    g.replace(g.find("VALUE"), 5, value);
    test::writeFile(dir + "/g.json", g);
    return test::shellQuote(dir + "/g.json");
  };
  CmdResult r = wg("validate " + withPreset("formula", "\"foo(a)\""));
  EXPECT_EQ(r.exit, 1) << r.err;
  EXPECT_NE(r.err.find("[WG038]"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("with preset 'worn'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("g.json:4:"), std::string::npos) << "at the preset's member\n" << r.err;
  r = wg("compile " + withPreset("inputs", "{\"a\": \"vec3\"}") + " -o " + dir + "/out");
  EXPECT_EQ(r.exit, 1) << r.err;
  EXPECT_NE(r.err.find("[WG029]"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out/g.glsl330.frag"));
  // The column is that of the unknown name in the file, escapes counted (found in review:
  // each \t counted one column when the preset was not applied).
  std::string escaped = withPreset("formula", "\"\\t\\t\\tfoo(a)\"");
  std::string line4 = test::splitLines(test::readFile(dir + "/g.json")).at(3);
  std::string at = "g.json:4:" + std::to_string(line4.find("foo(") + 1) + ": error: [WG038]";
  for (const char* applied : {"", " --preset worn"}) {
    r = wg("validate " + escaped + applied);
    EXPECT_EQ(r.exit, 1) << r.err;
    EXPECT_NE(r.err.find(at), std::string::npos) << applied << ": expected " << at << "\n" << r.err;
  }
  // A good preset passes, applied or not.
  r = wg("validate " + withPreset("formula", "\"a * 3.0\""));
  EXPECT_EQ(r.exit, 0) << r.err;
  r = wg("validate " + withPreset("formula", "\"a * 3.0\"") + " --preset worn");
  EXPECT_EQ(r.exit, 0) << r.err;
  fs::remove_all(dir);
}

TEST(CliPreset, EveryPresetOfEveryExampleValidates) {
  for (const auto& path : test::exampleGraphs()) {
    auto g = nlohmann::json::parse(test::readFile(path));
    if (!g.contains("presets")) continue;
    for (const auto& [name, values] : g["presets"].items()) {
      SCOPED_TRACE(path + " --preset " + name);
      CmdResult r = wg("validate " + test::shellQuote(path) + " --preset " + name);
      EXPECT_EQ(r.exit, 0) << r.err;
    }
  }
}

}  // namespace
}  // namespace wg
