// `watergraph tune` end to end on a graph small enough to know the answer: a Fresnel model
// (any level below exact is far off at grazing angles) and a colour variation weighted so
// lightly that switching it off (bypass) stays far within a 60 dB budget. The tuner must
// switch the variation off and keep the exact Fresnel; a budget nothing meets is one
// message and exit 1; --write-preset writes a preset that compiles and is canonical.
#include <filesystem>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "test_support.h"

namespace wg {
namespace {

using test::CmdResult;
CmdResult wg(const std::string& args) { return test::runWatergraph(args); }

// `presets` is the graph's "presets" member ("" for none).
std::string twoKnobGraph(const std::string& presets) {
  return R"({"version": 1, "name": "two_knobs", )" + presets + R"("nodes": [
    {"id": "f", "type": "fresnel", "options": {"model": "schlick"}},
    {"id": "tint", "type": "mix", "inputs": {"a": [0, 0.15, 0.25], "b": [0.6, 0.75, 0.9], "t": "f.reflectance"}},
    {"id": "cv", "type": "color_variation",
     "inputs": {"color": "tint.out", "slope_strength": 0.001, "noise_strength": 0.001, "trough": 0}}],
    "outputs": {"fragment": {"color": "cv.color"}}})";
}

const std::string kSmall = " --size 64x36 --runs 1 --cameras above,grazing --times 1,3.5,20";

// dir/g.json compiled as written keeps its colour variation; with the written `fast`
// preset the variation is gone.
void expectFastPresetDropsTheVariation(const std::string& dir) {
  std::string g = test::shellQuote(dir + "/g.json");
  CmdResult plain = wg("compile " + g + " -o " + test::shellQuote(dir + "/plain") + " --target glsl330");
  CmdResult fast = wg("compile " + g + " -o " + test::shellQuote(dir + "/fast") + " --target glsl330 --preset fast");
  ASSERT_EQ(plain.exit, 0) << plain.err;
  ASSERT_EQ(fast.exit, 0) << fast.err;
  EXPECT_NE(test::readFile(dir + "/plain/g.glsl330.frag").find("wg_color_variation"), std::string::npos);
  EXPECT_EQ(test::readFile(dir + "/fast/g.glsl330.frag").find("wg_color_variation"), std::string::npos);
}

TEST(TuneCli, FindsTheKnownBestConfiguration) {
  std::string dir = test::makeTempDir("wg_tune_");
  test::writeFile(dir + "/g.json", twoKnobGraph(""));
  CmdResult r = wg("tune " + test::shellQuote(dir + "/g.json") + " --min-psnr 60" + kSmall + " --plot " +
                test::shellQuote(dir + "/tune.svg"));
  ASSERT_EQ(r.exit, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("chosen: f.model=exact, cv.bypass=true\n"), std::string::npos) << r.out;
  // Switching cv off drops what it draws: said before the configuration, with the way out.
  const size_t off = r.out.find("switched off: cv (what it draws is gone from the chosen configuration; forbid it "
                                "with --keep cv, or --no-bypass)\n");
  EXPECT_NE(off, std::string::npos) << r.out;
  EXPECT_LT(off, r.out.find("chosen: ")) << r.out;
  EXPECT_NE(r.out.find("| 1 | cv.bypass | true |"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("| 2 |"), std::string::npos) << "one step only:\n" << r.out;
  EXPECT_NE(r.out.find("  f.model=schlick: fails the budget: worst PSNR "), std::string::npos) << "why it stopped:\n" << r.out;
  std::string svg = test::readFile(dir + "/tune.svg");
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("cv.bypass=true"), std::string::npos);
  EXPECT_NE(svg.find("f.model=schlick"), std::string::npos);
  EXPECT_NE(svg.find("Pareto"), std::string::npos);
  std::filesystem::remove_all(dir);
}

// --keep cv (or --no-bypass) leaves the colour variation drawn: the only other knob, the
// Fresnel model, fails the 60 dB budget at every cheaper level, so nothing is found, and no
// configuration tried switches cv off. A --keep naming no node tune could switch off is a
// usage error naming it and the nodes that can be.
TEST(TuneCli, KeepAndNoBypassForbidSwitchingNodesOff) {
  std::string dir = test::makeTempDir("wg_tune_");
  test::writeFile(dir + "/g.json", twoKnobGraph(""));
  const std::string g = test::shellQuote(dir + "/g.json");
  for (const char* flag : {" --keep cv", " --no-bypass"}) {
    SCOPED_TRACE(flag);
    CmdResult r = wg("tune " + g + " --min-psnr 60" + kSmall + flag);
    EXPECT_EQ(r.exit, 1) << r.out << r.err;
    EXPECT_EQ(r.out.find("cv.bypass"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("switched off"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("1 knob"), std::string::npos) << r.out;
  }
  for (const char* bad : {"f", "nosuch", "cv,", ""}) {
    SCOPED_TRACE(bad);
    CmdResult r = wg("tune " + g + " --min-psnr 60" + kSmall + " --keep " + test::shellQuote(bad));
    EXPECT_EQ(r.exit, 2) << r.out << r.err;
    EXPECT_NE(r.err.find("--keep"), std::string::npos) << r.err;
  }
  CmdResult r = wg("tune " + g + " --min-psnr 60" + kSmall + " --keep nosuch");
  EXPECT_NE(r.err.find("'nosuch', which is not a node tune could switch off (those are: cv)"), std::string::npos) << r.err;
  std::filesystem::remove_all(dir);
}

TEST(TuneCli, ABudgetNothingMeetsIsOneMessageAndExit1) {
  std::string dir = test::makeTempDir("wg_tune_");
  test::writeFile(dir + "/g.json", twoKnobGraph(""));
  std::string before = test::readFile(dir + "/g.json");
  CmdResult r = wg("tune " + test::shellQuote(dir + "/g.json") + " --max-abs-error 0 --write-preset fast" + kSmall);
  EXPECT_EQ(r.exit, 1) << r.out << r.err;
  EXPECT_NE(r.err.find("error: no configuration cheaper than the reference meets the budget"), std::string::npos) << r.err;
  EXPECT_EQ(test::readFile(dir + "/g.json"), before) << "nothing written";
  test::writeFile(dir + "/plain.json", R"({"version": 1, "name": "plain", "nodes": [{"id": "n", "type": "normal"}],
    "outputs": {"fragment": {"color": "n.out"}}})");
  r = wg("tune " + test::shellQuote(dir + "/plain.json") + " --min-psnr 45" + kSmall);
  EXPECT_EQ(r.exit, 1);
  EXPECT_NE(r.err.find("the graph has no quality knob to tune"), std::string::npos) << r.err;
  r = wg("tune " + test::shellQuote(dir + "/g.json") + kSmall);
  EXPECT_EQ(r.exit, 2);
  EXPECT_NE(r.err.find("give a budget"), std::string::npos) << r.err;
  // A budget or time that is not a finite float would compare false everywhere or reach
  // u_time as Inf: a usage error, before anything is rendered.
  for (const char* bad : {" --min-psnr nan --times 1", " --max-abs-error inf --times 1", " --min-psnr 45 --times 1,1e300"}) {
    r = wg("tune " + test::shellQuote(dir + "/g.json") + bad + " --size 64x36 --runs 1");
    EXPECT_EQ(r.exit, 2) << bad;
    EXPECT_NE(r.err.find("within float range"), std::string::npos) << bad << ": " << r.err;
  }
  // Decimal numbers only (strtod took a leading space and hexadecimal), and at most 64.
  std::string many;
  for (int i = 0; i < 65; ++i) many += (i ? "," : "") + std::to_string(i);
  for (const std::string& bad : {std::string("' 1'"), std::string("0x10"), std::string("1,,2"), many}) {
    r = wg("tune " + test::shellQuote(dir + "/g.json") + " --min-psnr 45 --size 64x36 --runs 1 --times " + bad);
    EXPECT_EQ(r.exit, 2) << bad;
    EXPECT_TRUE(r.err.find("finite decimal numbers") != std::string::npos || r.err.find("at most 64") != std::string::npos ||
                r.err.find("has an empty entry") != std::string::npos)
        << bad << ": " << r.err;
  }
  // An empty preset name was taken as "none" (exit 0, nothing written, nothing said).
  r = wg("tune " + test::shellQuote(dir + "/g.json") + " --min-psnr 45 --write-preset ''" + kSmall);
  EXPECT_EQ(r.exit, 2);
  EXPECT_NE(r.err.find("is not an identifier"), std::string::npos) << r.err;
  EXPECT_EQ(test::readFile(dir + "/g.json"), before) << "nothing written";
  std::filesystem::remove_all(dir);
}

// An existing preset of the name is replaced in its place; the file is canonical after
// (fmt changes nothing) and `compile --preset fast` compiles the variation out.
TEST(TuneCli, WritesAPresetThatCompilesAndIsCanonical) {
  std::string dir = test::makeTempDir("wg_tune_");
  test::writeFile(dir + "/g.json", twoKnobGraph(R"("presets": {"fast": {"f.model": "power"}, "exact": {"f.model": "exact"}}, )"));
  std::string g = test::shellQuote(dir + "/g.json");
  CmdResult r = wg("tune " + g + " --min-psnr 60 --write-preset fast" + kSmall);
  ASSERT_EQ(r.exit, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("wrote preset 'fast'"), std::string::npos) << r.out;
  auto written = nlohmann::ordered_json::parse(test::readFile(dir + "/g.json"));
  EXPECT_EQ(written["presets"].dump(), R"({"fast":{"f.model":"exact","cv.bypass":true},"exact":{"f.model":"exact"}})");
  std::string text = test::readFile(dir + "/g.json");
  CmdResult fmt = wg("fmt " + g);
  EXPECT_EQ(fmt.exit, 0) << fmt.err;
  EXPECT_EQ(test::readFile(dir + "/g.json"), text) << "fmt changed the written file";
  expectFastPresetDropsTheVariation(dir);
  std::filesystem::remove_all(dir);
}

// A knob inside a subgraph instance is tuned like the graph's own, named by the instance
// ("v/cv.bypass"), and the preset written sets it: compiled with it, the variation is gone.
TEST(TuneCli, TunesAndWritesAKnobInsideASubgraphInstance) {
  std::string dir = test::makeTempDir("wg_tune_");
  std::filesystem::create_directories(dir + "/lib");
  test::writeFile(dir + "/lib/vary.json", R"({"version": 1, "name": "vary",
    "interface": {"outputs": {"color": {"type": "vec3", "source": "cv.color"}}},
    "parameters": {"color": {"type": "vec3", "default": [0, 0, 0], "min": 0, "max": 1}},
    "nodes": [{"id": "cv", "type": "color_variation",
               "inputs": {"color": "$color", "slope_strength": 0.001, "noise_strength": 0.001, "trough": 0}}]})");
  test::writeFile(dir + "/g.json", R"({"version": 1, "name": "nested", "imports": {"vary": "lib/vary.json"}, "nodes": [
    {"id": "f", "type": "fresnel", "options": {"model": "schlick"}},
    {"id": "tint", "type": "mix", "inputs": {"a": [0, 0.15, 0.25], "b": [0.6, 0.75, 0.9], "t": "f.reflectance"}},
    {"id": "v", "type": "vary", "inputs": {"color": "tint.out"}}],
    "outputs": {"fragment": {"color": "v.color"}}})");
  std::string g = test::shellQuote(dir + "/g.json");
  CmdResult r = wg("tune " + g + " --min-psnr 60 --write-preset fast" + kSmall);
  ASSERT_EQ(r.exit, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("chosen: f.model=exact, v/cv.bypass=true\n"), std::string::npos) << r.out;
  auto written = nlohmann::ordered_json::parse(test::readFile(dir + "/g.json"));
  EXPECT_EQ(written["presets"].dump(), R"({"fast":{"f.model":"exact","v/cv.bypass":true}})");
  expectFastPresetDropsTheVariation(dir);
  std::filesystem::remove_all(dir);
}

// The wave count: the third wave is a 10 micrometre ripple, the second a real wave. The
// tuner keeps the first two (max_waves 2, the level below the whole list) and no fewer.
TEST(TuneCli, DropsTheWavesThatStayWithinTheBudget) {
  std::string dir = test::makeTempDir("wg_tune_");
  test::writeFile(dir + "/w.json", R"({"version": 1, "name": "w", "nodes": [
    {"id": "waves", "type": "gerstner_waves", "options": {"waves": [
      {"direction": [1, 0.2], "steepness": 0.4, "wavelength": 8},
      {"direction": [0.3, 1], "steepness": 0.3, "wavelength": 5},
      {"direction": [-0.7, 0.6], "steepness": 0.2, "wavelength": 3, "amplitude": 0.00001}]}}],
    "outputs": {"fragment": {"color": "waves.normal"}}})");
  CmdResult r = wg("tune " + test::shellQuote(dir + "/w.json") + " --min-psnr 60" + kSmall);
  ASSERT_EQ(r.exit, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("chosen: waves.max_waves=2\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  waves.max_waves=1: fails the budget"), std::string::npos) << r.out;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace wg
