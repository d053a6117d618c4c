// `watergraph render` as a user runs it.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <sys/stat.h>

#include <gtest/gtest.h>

#include "runtime/image.h"
#include "test_support.h"

namespace wg {
namespace {

std::string render(const std::string& args, int* code) {
  std::string out;
  *code = test::runCommand(test::watergraphBinary() + " render " + args, &out);
  return out;
}

TEST(RenderCli, WritesAPngAndPrintsStats) {
  std::string dir = test::makeTempDir("wg_render_");
  std::string png = dir + "/sub/lake.png";
  int code = -1;
  std::string out = render(test::sourcePath("graphs/lake.json") + " -o " + png +
                               " --size 160x90 --camera grazing --time 2 --frames 3 --stats",
                           &code);
  EXPECT_EQ(code, 0) << out;
  ASSERT_TRUE(std::filesystem::exists(png)) << out;
  rt::Image img = rt::readPng(png);
  EXPECT_EQ(img.width, 160);
  EXPECT_EQ(img.height, 90);
  EXPECT_NE(out.find("passes: opaque_scene, water_surface, output_transform"), std::string::npos) << out;
  EXPECT_NE(out.find("render targets: 2"), std::string::npos) << out;
  EXPECT_NE(out.find("RGBA16F + DEPTH32F"), std::string::npos) << out;
  EXPECT_NE(out.find("median"), std::string::npos) << out;
  // Nothing but the PNG is left in the folder (the temporary was renamed).
  size_t files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir + "/sub")) ++files;
  EXPECT_EQ(files, 1u);
  std::filesystem::remove_all(dir);
}

// A spectral ocean's simulation runs first and its textures are reported beside the render
// targets: open_ocean's three 256^2 cascades, each 7,603,200 B (ocean_gpu_cascade_test
// derives the sizes) and 1,747,616 B of filtered pyramids (the moments map's 87,381 texels
// over its nine levels and the slope map's 21,845 below level 0, RGBA32F), and the foam of
// its two longest, four R32F 256^2 maps each (1,048,576 B); a graph without an ocean prints
// no such line.
TEST(RenderCli, StatsReportTheOceanSimulation) {
  std::string dir = test::makeTempDir("wg_render_");
  int code = -1;
  std::string out =
      render(test::sourcePath("graphs/open_ocean.json") + " -o " + dir + "/o.png --size 64x36 --stats", &code);
  EXPECT_EQ(code, 0) << out;
  EXPECT_NE(out.find("passes: ocean_simulation, "), std::string::npos) << out;
  EXPECT_NE(out.find("ocean simulation: 30149600 bytes"), std::string::npos) << out;
  out = render(test::sourcePath("graphs/lake.json") + " -o " + dir + "/l.png --size 64x36 --stats", &code);
  EXPECT_EQ(code, 0) << out;
  EXPECT_EQ(out.find("ocean simulation:"), std::string::npos) << out;
  std::filesystem::remove_all(dir);
}

TEST(RenderCli, Es300Target) {
  std::string dir = test::makeTempDir("wg_render_");
  int code = -1;
  std::string out = render(test::sourcePath("graphs/shelf.json") + " -o " + dir + "/s.png --size 64x36 --target es300", &code);
  EXPECT_EQ(code, 0) << out;
  EXPECT_TRUE(std::filesystem::exists(dir + "/s.png"));
  std::filesystem::remove_all(dir);
}

// The vk450 SPIR-V on Vulkan under the validation layer, with the stats naming the device.
TEST(RenderCli, Vk450TargetUnderValidation) {
  std::string dir = test::makeTempDir("wg_render_");
  int code = -1;
  std::string out = render(test::sourcePath("graphs/classic_webgl.json") + " -o " + dir +
                               "/c.png --size 64x36 --target vk450 --vk-validation --stats",
                           &code);
  EXPECT_EQ(code, 0) << out;
  EXPECT_TRUE(std::filesystem::exists(dir + "/c.png"));
  EXPECT_NE(out.find("vk450 on llvmpipe"), std::string::npos) << out;
  EXPECT_NE(out.find("(Vulkan 1."), std::string::npos) << out;
  EXPECT_NE(out.find("passes: depth_prepass, planar_reflection, refraction, opaque_scene, water_surface"), std::string::npos) << out;
  std::filesystem::remove_all(dir);
}

TEST(RenderCli, UsageErrorsExit2) {
  std::string dir = test::makeTempDir("wg_render_");
  std::string lake = test::sourcePath("graphs/lake.json");
  int code = -1;
  std::string out = render(lake + " -o " + dir + "/x.png --camera sideways", &code);
  EXPECT_EQ(code, 2) << out;
  EXPECT_NE(out.find("sideways"), std::string::npos) << out;
  out = render(lake + " -o " + dir + "/x.png --size 12by8", &code);
  EXPECT_EQ(code, 2) << out;
  out = render(lake + " -o " + dir + "/x.png --target msl", &code);  // compiled, never run here
  EXPECT_EQ(code, 2) << out;
  out = render(lake + " -o " + dir + "/x.png --vk-validation", &code);  // the layer checks Vulkan only
  EXPECT_EQ(code, 2) << out;
  EXPECT_NE(out.find("--vk-validation needs --target vk450"), std::string::npos) << out;
  out = render(test::sourcePath("graphs/no_such_graph.json") + " -o " + dir + "/x.png", &code);
  EXPECT_EQ(code, 2) << out;
  // Numbers that would reach a uniform as NaN or Inf (CLI11 converts "nan", "inf" and
  // 1e300 without complaint, and its Range lets NaN through).
  for (const char* bad : {"--time nan", "--time 1e300", "--time -inf", "--sun-azimuth nan", "--sun-elevation nan",
                          "--sun-elevation inf"}) {
    out = render(lake + " -o " + dir + "/x.png --size 16x9 " + bad, &code);
    EXPECT_EQ(code, 2) << bad << ": " << out;
    EXPECT_NE(out.find("must be a finite number within float range"), std::string::npos) << bad << ": " << out;
  }
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.png"));
  std::filesystem::remove_all(dir);
}

// The output transform's flags: an unknown tone mapper, or an exposure that is not a finite
// number in [-20, 20], is a usage error naming the flag, before anything is rendered; a
// valid pair changes the picture.
TEST(RenderCli, ToneMapperAndExposureFlags) {
  std::string dir = test::makeTempDir("wg_render_view_");
  std::string lake = test::sourcePath("graphs/lake.json");
  int code = -1;
  for (const char* bad : {"--tonemap filmic", "--tonemap ''", "--exposure nan", "--exposure inf", "--exposure 21",
                          "--exposure -20.5", "--exposure 1e300"}) {
    std::string out = render(lake + " -o " + dir + "/x.png --size 16x9 " + bad, &code);
    EXPECT_EQ(code, 2) << bad << ": " << out;
    const std::string flag = std::string(bad).substr(0, std::string(bad).find(' '));
    EXPECT_NE(out.find(flag + ":"), std::string::npos) << bad << ": " << out;
    EXPECT_EQ(test::splitLines(out).size(), 1u) << "one line: " << out;
  }
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.png"));
  std::string out = render(lake + " -o " + dir + "/plain.png --size 32x18", &code);
  EXPECT_EQ(code, 0) << out;
  out = render(lake + " -o " + dir + "/agx.png --size 32x18 --tonemap agx --exposure -1", &code);
  EXPECT_EQ(code, 0) << out;
  EXPECT_NE(rt::readPng(dir + "/plain.png").rgba8, rt::readPng(dir + "/agx.png").rgba8);
  std::filesystem::remove_all(dir);
}

// The PNG is written as every output file is: a temporary, then a rename. A FIFO, a device
// or a folder at the output path is refused, never replaced by a regular file (as root, a
// rename onto /dev/full used to succeed and leave a regular file there).
TEST(RenderCli, AnOutputPathThatIsNotARegularFileIsRefusedAndKept) {
  std::string dir = test::makeTempDir("wg_render_");
  std::string lake = test::sourcePath("graphs/lake.json");
  std::string fifo = dir + "/fifo.png", folder = dir + "/folder.png";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  std::filesystem::create_directory(folder);
  // (Not a real device: as root, a regression would replace it for the whole machine.)
  for (const std::string& path : {fifo, folder}) {
    int code = -1;
    std::string out = render(lake + " --size 16x9 -o " + path, &code);
    EXPECT_EQ(code, 2) << path << ": " << out;
    EXPECT_NE(out.find(path + ": error: [WG051] cannot replace: not a regular file"), std::string::npos) << out;
  }
  EXPECT_TRUE(std::filesystem::is_fifo(fifo));
  EXPECT_TRUE(std::filesystem::is_directory(folder));
  std::vector<std::string> left;
  for (const auto& e : std::filesystem::directory_iterator(dir)) left.push_back(e.path().filename().string());
  EXPECT_EQ(left.size(), 2u) << "a temporary was left behind";
  std::filesystem::remove_all(dir);
}

// glvnd with no vendor library stands in for a machine without an EGL driver.
TEST(RenderCli, NoEglDriverIsOneLineAndExit2) {
  std::string dir = test::makeTempDir("wg_render_");
  std::string out;
  int code = test::runCommand("__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent/vendor.json " + test::watergraphBinary() +
                                  " render " + test::sourcePath("graphs/lake.json") + " -o " + dir + "/x.png --size 32x18",
                              &out);
  EXPECT_EQ(code, 2) << out;
  EXPECT_NE(out.find("error: cannot render: "), std::string::npos) << out;
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 1) << out;
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.png"));
  std::filesystem::remove_all(dir);
}

// Found in review: a subgraph in another folder that samples its own PNG. The loader makes
// its path relative to the top graph ("lib/r.png"); render, compile --textures (and the
// editor, through the same origins) joined it with the subgraph's folder once more and
// looked for lib/lib/r.png: an error, or, with a file there, the wrong texture drawn.
TEST(RenderCli, ASubgraphsTextureIsReadFromTheSubgraphsFolder) {
  std::string dir = test::makeTempDir("wg_render_subtex_");
  std::filesystem::create_directories(dir + "/lib/lib");
  auto solid = [](const std::string& path, unsigned char r, unsigned char g) {
    rt::Image img;
    img.width = img.height = 2;
    for (int i = 0; i < 4; ++i) img.rgba8.insert(img.rgba8.end(), {r, g, 0, 255});
    rt::writePng(path, img);
  };
  solid(dir + "/lib/r.png", 255, 0);      // the subgraph's texture: red
  solid(dir + "/lib/lib/r.png", 0, 255);  // a decoy where the doubled path pointed: green
  test::writeFile(dir + "/lib/s.json", R"({"version": 1, "name": "s",
  "interface": {"outputs": {"o": {"type": "vec3", "source": "t.rgb"}}},
  "nodes": [{"id": "t", "type": "texture_sample", "options": {"texture": "r.png"}}]})");
  test::writeFile(dir + "/top.json", R"({"version": 1, "name": "top", "imports": {"s": "lib/s.json"},
  "nodes": [{"id": "a", "type": "s"}], "outputs": {"fragment": {"color": "a.o"}}})");
  int code = -1;
  std::string out = render(dir + "/top.json -o " + dir + "/top.png --size 16x9", &code);
  ASSERT_EQ(code, 0) << out;
  rt::Image img = rt::readPng(dir + "/top.png");
  ASSERT_EQ(img.rgba8.size(), 16u * 9u * 4u);
  const size_t water = (8u * 16u + 8u) * 4u;  // bottom row, middle: the water plane (sky above)
  EXPECT_GT(img.rgba8[water], 200) << "red channel";
  EXPECT_LT(img.rgba8[water + 1], 50) << "green channel: the decoy at lib/lib/r.png was drawn";
  std::string compiled;
  code = test::runCommand(test::watergraphBinary() + " compile " + dir + "/top.json -o " + dir + "/out --target es300 --textures",
                          &compiled);
  ASSERT_EQ(code, 0) << compiled;
  rt::Image exported = rt::readPng(dir + "/out/top.t0_r.png");
  ASSERT_FALSE(exported.rgba8.empty());
  EXPECT_EQ(exported.rgba8[0], 255);
  EXPECT_EQ(exported.rgba8[1], 0);
  std::filesystem::remove_all(dir);
}

TEST(RenderCli, HelpShowsExamples) {
  int code = -1;
  std::string out = render("--help", &code);
  EXPECT_EQ(code, 0);
  EXPECT_NE(out.find("watergraph render graphs/lake.json -o lake.png"), std::string::npos) << out;
  EXPECT_NE(out.find("--camera"), std::string::npos);
}

}  // namespace
}  // namespace wg
