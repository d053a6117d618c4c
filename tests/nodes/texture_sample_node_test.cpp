// texture_sample: its double reference against texel values computed by hand on a 4x4 PNG
// the test writes (tests/sampler_test_texture.h), for each wrap mode, filter and colour
// space and for mip levels chosen by the uv gradient; the node compiled for every target;
// the sampler state in the shader interface and the manifest; bad texture options.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "codegen/compile.h"
#include "codegen/cpu_backend.h"
#include "core/graph_io.h"
#include "nodes/registry.h"
#include "nodes/texture_source.h"
#include "sampler_test_texture.h"
#include "test_support.h"

namespace wg {
namespace {

namespace fs = std::filesystem;

class TextureSampleNode : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = test::makeTempDir("wg_texture_sample_");
    test::writeFile(dir + "/ramp.png", test::rampPng());
  }
  void TearDown() override { fs::remove_all(dir); }

  // rgba at (u, v) with these options on ramp.png, the uv gradient from `env`.
  Value sample(double u, double v, nlohmann::json options, EvalEnvironment env = EvalEnvironment{}) {
    options["texture"] = "ramp.png";
    const NodeSpec* spec = defaultRegistry().find("texture_sample");
    auto out = evaluateNode(*spec, options, {{"uv", Value::vector({u, v})}}, env, &textures, dir);
    return out.at(static_cast<size_t>(spec->outputIndex("rgba")));
  }

  // Compiles `graph` saved in the folder; nullopt with the diagnostics' text in *messages.
  std::optional<CompileResult> compileHere(const std::string& graph, std::string* messages) {
    test::writeFile(dir + "/g.json", graph);
    Diagnostics diags;
    std::optional<CompileResult> result;
    if (auto g = loadGraphFile(dir + "/g.json", diags)) result = compileGraph(*g, defaultRegistry(), CompileOptions{}, diags);
    for (const auto& d : diags.sorted()) *messages += formatText(d) + "\n";
    if (diags.hasErrors()) return std::nullopt;
    return result;
  }

  std::string dir;
  TextureCache textures;
};

std::string sampleNode(const std::string& id, const nlohmann::json& options) {
  return "{\"id\": \"" + id + "\", \"type\": \"texture_sample\", \"options\": " + options.dump() + "}";
}

constexpr double kExact = 1e-12;

TEST_F(TextureSampleNode, NearestReadsTheTexelUnderUvForEachWrap) {
  nlohmann::json linearNearest = {{"filter", "nearest"}, {"color_space", "linear"}};
  // (0.3, 0.6): texel (floor 1.2, floor 2.4) = (1, 2): r = 16 + 128.
  EXPECT_NEAR(sample(0.3, 0.6, linearNearest)[0], 144 / 255.0, kExact);
  // Exactly on the edge between texels 0 and 1 (u 4 = 1.0): GL takes the texel above.
  EXPECT_NEAR(sample(0.25, 0.0, linearNearest)[0], 16 / 255.0, kExact);
  // u = -0.3 (u 4 = -1.2, texel -2): repeat reads texel 2, clamp texel 0, mirror texel 1.
  for (auto [wrap, r] : {std::pair{"repeat", 32}, std::pair{"clamp", 0}, std::pair{"mirror", 16}}) {
    nlohmann::json o = linearNearest;
    o["wrap"] = wrap;
    EXPECT_NEAR(sample(-0.3, 0.0, o)[0], r / 255.0, kExact) << wrap;
  }
  // u = 1.1 (texel 4): repeat texel 0, clamp texel 3, mirror texel 3 (the edge repeats).
  for (auto [wrap, r] : {std::pair{"repeat", 0}, std::pair{"clamp", 48}, std::pair{"mirror", 48}}) {
    nlohmann::json o = linearNearest;
    o["wrap"] = wrap;
    EXPECT_NEAR(sample(1.1, 0.0, o)[0], r / 255.0, kExact) << wrap;
  }
  // A million periods away the wrap is still exact in double: 1e6 + 0.3 is texel 1 again.
  EXPECT_NEAR(sample(1e6 + 0.3, 0.0, linearNearest)[0], 16 / 255.0, kExact);
  nlohmann::json mirror = linearNearest;
  mirror["wrap"] = "mirror";
  EXPECT_NEAR(sample(-1e6 - 0.3, 0.0, mirror)[0], 16 / 255.0, kExact);  // an even number of mirrors
}

TEST_F(TextureSampleNode, LinearBlendsTexelCentresForEachWrap) {
  nlohmann::json linear = {{"color_space", "linear"}};
  // (0.25, 0.5): halfway between texel columns 0, 1 and rows 1, 2: r = 16 0.5 + 64 1.5.
  Value mid = sample(0.25, 0.5, linear);
  EXPECT_NEAR(mid[0], 104 / 255.0, kExact);
  EXPECT_NEAR(mid[3], 239 / 255.0, kExact);  // alpha: (255 + 223) / 2
  // A texel centre reads that texel alone: (1.5/4, 2.5/4) is texel (1, 2).
  EXPECT_NEAR(sample(1.5 / 4, 2.5 / 4, linear)[0], 144 / 255.0, kExact);
  // u = -0.05 (u 4 - 0.5 = -0.7): texels -1 and 0 weighted 0.7 and 0.3; rows 1 and 2 halved.
  for (auto [wrap, r] : {std::pair{"repeat", 48 * 0.7 + 96}, std::pair{"clamp", 96.0}, std::pair{"mirror", 96.0}}) {
    nlohmann::json o = linear;
    o["wrap"] = wrap;
    EXPECT_NEAR(sample(-0.05, 0.5, o)[0], r / 255.0, kExact) << wrap;
  }
  // u = 1.05 (4.2 - 0.5 = 3.7): texels 3 and 4 weighted 0.3 and 0.7: repeat blends texel 0 in,
  // clamp and mirror read texel 3 twice.
  for (auto [wrap, r] : {std::pair{"repeat", 48 * 0.3 + 96}, std::pair{"clamp", 48.0 + 96}, std::pair{"mirror", 48.0 + 96}}) {
    nlohmann::json o = linear;
    o["wrap"] = wrap;
    EXPECT_NEAR(sample(1.05, 0.5, o)[0], r / 255.0, kExact) << wrap;
  }
}

TEST_F(TextureSampleNode, SrgbDecodesEachTexelBeforeFiltering) {
  // g is 255 in column 0 and 0 in column 1: halfway the decoded texels average to 0.5,
  // where decoding the filtered byte 127.5 would give 0.2140.
  Value srgb = sample(0.25, 0.5, nlohmann::json::object());  // srgb is the default
  EXPECT_NEAR(srgb[1], 0.5, kExact);
  // r bytes 16 0.5 + 64 1.5 around: each of the four texels decoded, then blended.
  auto decode = [](double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); };
  double r = (decode(64 / 255.0) + decode(80 / 255.0) + decode(128 / 255.0) + decode(144 / 255.0)) / 4;
  EXPECT_NEAR(srgb[0], r, kExact);
  // Alpha is never decoded.
  EXPECT_NEAR(srgb[3], 239 / 255.0, kExact);
  // One value worked by hand: byte 128 is 0.21586050011389926 linear; nearest reads it as that.
  test::writeFile(dir + "/grey.png", test::samplerTestPng(1, 1, [](int, int, int) { return 128; }));
  const NodeSpec* spec = defaultRegistry().find("texture_sample");
  auto out = evaluateNode(*spec, {{"texture", "grey.png"}, {"filter", "nearest"}}, {{"uv", Value::vector({0.5, 0.5})}},
                          EvalEnvironment{}, &textures, dir);
  EXPECT_NEAR(out[0][0], 0.21586050011389926, kExact);
  EXPECT_NEAR(out[1][0], 128 / 255.0, kExact);  // alpha
}

TEST_F(TextureSampleNode, MipmappedPicksTheLevelFromTheUvGradient) {
  nlohmann::json mip = {{"filter", "mipmapped"}, {"color_space", "linear"}};
  auto gradient = [](double dudx) {
    EvalEnvironment env;
    env.uvDx = Value::vector({dudx, 0});
    env.uvDy = Value::vector({0, dudx});
    return env;
  };
  // No gradient: level 0, as linear. (0.25, 0.5) as in the linear test.
  EXPECT_NEAR(sample(0.25, 0.5, mip)[0], 104 / 255.0, kExact);
  // rho = 4 dudx. Level 1 (2x2) holds the block averages: r = 40 + 32 i + 128 j, b = 96.
  Value l1 = sample(0.25, 0.25, mip, gradient(0.5));  // lambda 1, texel (0, 0) of level 1
  EXPECT_NEAR(l1[0], 40 / 255.0, kExact);
  EXPECT_NEAR(l1[2], 96 / 255.0, kExact);
  // Level 2 (1x1) is their average, r = 120; lambda 1.5 blends levels 1 and 2 halfway.
  EXPECT_NEAR(sample(0.25, 0.25, mip, gradient(std::sqrt(8.0) / 4))[0], (40 + 120) / 2 / 255.0, 1e-9);
  // From the last level on (lambda 2 and beyond) the 1x1 level alone.
  EXPECT_NEAR(sample(0.9, 0.1, mip, gradient(1.0))[0], 120 / 255.0, kExact);
  EXPECT_NEAR(sample(0.9, 0.1, mip, gradient(1e3))[0], 120 / 255.0, kExact);
  // Magnification (lambda < 0) stays on level 0.
  EXPECT_NEAR(sample(0.25, 0.5, mip, gradient(0.1))[0], 104 / 255.0, kExact);
  // sRGB levels are averaged in linear and stored as sRGB bytes: g of level 1 column 0 is
  // (1 + 0) / 2 = 0.5 linear, stored as byte round(255 * 0.7354) = 188, read back 0.50289.
  nlohmann::json mipSrgb = {{"filter", "mipmapped"}};
  EXPECT_NEAR(sample(0.25, 0.25, mipSrgb, gradient(0.5))[1], 0.5028864580325687, kExact);
}

TEST_F(TextureSampleNode, CompilesForEveryTargetWithOneSamplerPerState) {
  // Two nodes read ramp.png with different wraps, a third shares the first's state.
  nlohmann::json a = {{"texture", "ramp.png"}, {"wrap", "clamp"}, {"filter", "mipmapped"}};
  nlohmann::json b = {{"texture", "ramp.png"}, {"wrap", "mirror"}, {"color_space", "linear"}};
  std::string nodes = sampleNode("a", a) + "," + sampleNode("b", b) + "," + sampleNode("c", a) +
                      ",{\"id\": \"s\", \"type\": \"add\", \"inputs\": {\"a\": \"a.rgb\", \"b\": \"b.rgb\"}}"
                      ",{\"id\": \"t\", \"type\": \"mul\", \"inputs\": {\"a\": \"s.out\", \"b\": \"c.alpha\"}}";
  std::string messages;
  auto result = compileHere(test::graphJson(nodes, "\"fragment\": {\"color\": \"t.out\"}"), &messages);
  ASSERT_TRUE(result) << messages;  // glslang accepted glsl330, es300 and vk450
  for (const char* target : {"glsl330", "es300", "vk450"}) EXPECT_NE(result->manifest.target(target), nullptr) << target;
  ASSERT_EQ(result->manifest.textures.size(), 2u);
  EXPECT_EQ(result->manifest.textures[0].sampler.wrap, TextureWrap::Clamp);
  EXPECT_EQ(result->manifest.textures[0].sampler.filter, TextureFilter::Mipmapped);
  EXPECT_EQ(result->manifest.textures[1].sampler.wrap, TextureWrap::Mirror);
  EXPECT_EQ(result->manifest.textures[1].sampler.colorSpace, TextureColorSpace::Linear);
  // The same texture in a vertex displacement compiles too (level 0 there).
  std::string vertex = sampleNode("h", {{"texture", "ramp.png"}, {"color_space", "linear"}}) +
                       ",{\"id\": \"p\", \"type\": \"world_position\"}"
                       ",{\"id\": \"d\", \"type\": \"add\", \"inputs\": {\"a\": \"p.out\", \"b\": \"h.rgb\"}}";
  messages.clear();
  EXPECT_TRUE(compileHere(test::graphJson(vertex, "\"vertex\": {\"position\": \"d.out\"}"), &messages)) << messages;
}

TEST_F(TextureSampleNode, TheManifestListsTheSamplerStateOnlyWhereItIsNotTheDefault) {
  nlohmann::json state = {{"texture", "ramp.png"}, {"wrap", "mirror"}, {"filter", "nearest"}};
  std::string nodes = sampleNode("a", state) +
                      ",{\"id\": \"f\", \"type\": \"texture_caustics\", \"options\": {\"texture\": \"ramp.png\"}}"
                      ",{\"id\": \"s\", \"type\": \"add\", \"inputs\": {\"a\": \"a.rgb\", \"b\": \"f.caustics\"}}";
  std::string messages;
  auto result = compileHere(test::graphJson(nodes, "\"fragment\": {\"color\": \"s.out\"}"), &messages);
  ASSERT_TRUE(result) << messages;
  nlohmann::json textures = nlohmann::json::parse(result->manifest.toJson().dump())["textures"];
  ASSERT_EQ(textures.size(), 2u) << textures.dump();
  EXPECT_EQ(textures[0]["sampler"], (nlohmann::json{{"wrap", "mirror"}, {"filter", "nearest"}, {"color_space", "srgb"}}));
  // texture_caustics reads ramp.png the default way: no "sampler", as in every manifest before.
  EXPECT_EQ(textures[1]["source"], "ramp.png");
  EXPECT_FALSE(textures[1].contains("sampler")) << textures[1].dump();
  // The state reads back, and the file with it.
  Manifest back = Manifest::fromJson(result->manifest.toJson());
  EXPECT_EQ(back.textures[0].sampler, result->manifest.textures[0].sampler);
  EXPECT_EQ(back.toJson().dump(), result->manifest.toJson().dump());
  // A state the compiler would not write is refused, naming the texture.
  nlohmann::json bad = result->manifest.toJson();
  bad["textures"][0]["sampler"]["wrap"] = "border";
  try {
    Manifest::fromJson(bad);
    ADD_FAILURE() << "an unknown wrap was accepted";
  } catch (const ManifestError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown wrap 'border'"), std::string::npos) << e.what();
  }
}

TEST_F(TextureSampleNode, BadTexturePathsAreGraphErrorsNamingTheNodeAndOption) {
  fs::create_directories(dir + "/../wg_texture_sample_outside");
  const std::string outside = fs::weakly_canonical(dir + "/../wg_texture_sample_outside").string();
  test::writeFile(outside + "/far.png", test::rampPng());
  test::writeFile(dir + "/fake.png", "GIF89a not a png");
  struct Bad {
    std::string path, why;
  };
  for (const Bad& bad : {Bad{"../wg_texture_sample_outside/far.png", "leaves the graph's folder"},
                         Bad{"fake.png", "not a PNG"}}) {
    std::string messages;
    auto result = compileHere(
        test::graphJson(sampleNode("tex", {{"texture", bad.path}}), "\"fragment\": {\"color\": \"tex.rgb\"}"), &messages);
    EXPECT_FALSE(result) << bad.path;
    EXPECT_NE(messages.find("g.json:1:"), std::string::npos) << messages;
    EXPECT_NE(messages.find("error: [WG030]"), std::string::npos) << messages;
    EXPECT_NE(messages.find("'tex'"), std::string::npos) << messages;
    EXPECT_NE(messages.find("'texture'"), std::string::npos) << messages;
    EXPECT_NE(messages.find(bad.why), std::string::npos) << messages;
  }
  fs::remove_all(outside);
}

}  // namespace
}  // namespace wg
