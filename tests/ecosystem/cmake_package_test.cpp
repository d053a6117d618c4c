// `cmake --install` gives a package that find_package(watergraph) finds; the example
// consumer (examples/cmake-consumer) builds against it, its shaders are compiled at build
// time by watergraph_add_shaders, it prints the manifest's uniforms and textures, and
// editing the graph, or the subgraph it imports, recompiles them.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "eco_support.h"

namespace wg {
namespace {

namespace fs = std::filesystem;
using test::shellQuote;

// The build folder of the watergraph under test: <build>/bin/watergraph.
std::string buildDir() { return fs::path(test::watergraphBinary()).parent_path().parent_path().string(); }

// Both generators a user meets: Ninja makes every output's folder before a command runs,
// Unix Makefiles (CMake's default) does not, so a depfile in a folder the compile makes must
// be written there by watergraph itself (issue 39).
class CMakePackage : public ::testing::TestWithParam<std::string> {};

void bumpMtime(const std::string& path) {
  auto t = fs::last_write_time(path);
  fs::last_write_time(path, t + std::chrono::seconds(2));
}

TEST_P(CMakePackage, InstallFindPackageAndRebuildOnGraphChange) {
  ASSERT_TRUE(fs::exists(buildDir() + "/CMakeCache.txt")) << buildDir();
  if (GetParam() == "Ninja" && !eco::haveTool("ninja")) GTEST_SKIP() << "no ninja";
  const std::string generator = " -G " + shellQuote(GetParam());
  eco::TempDir tmp;
  std::string prefix = tmp / "prefix";
  auto r = eco::sh("cmake --install " + shellQuote(buildDir()) + " --prefix " + shellQuote(prefix));
  ASSERT_EQ(r.exit, 0) << r.out << r.err;
  for (const char* f : {"bin/watergraph", "include/watergraph/core/graph.h", "include/watergraph/codegen/compile.h",
                        "include/watergraph/core/diagnostic_codes.def", "lib/cmake/watergraph/watergraphConfig.cmake",
                        "lib/cmake/watergraph/watergraphConfigVersion.cmake",
                        "lib/cmake/watergraph/WatergraphShaders.cmake", "lib/cmake/watergraph/watergraphTargets.cmake"})
    EXPECT_TRUE(fs::exists(prefix + "/" + f)) << f;
  auto version = eco::sh(shellQuote(prefix + "/bin/watergraph") + " --version");
  EXPECT_EQ(version.exit, 0);

  // A copy of the consumer, so the test can edit its graph.
  std::string src = tmp / "consumer";
  fs::copy(test::sourcePath("examples/cmake-consumer"), src, fs::copy_options::recursive);
  std::string bin = tmp / "consumer-build";
  r = eco::sh("cmake -S " + shellQuote(src) + " -B " + shellQuote(bin) + generator +
              " -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=" + shellQuote(prefix));
  ASSERT_EQ(r.exit, 0) << r.out << r.err;
  r = eco::sh("cmake --build " + shellQuote(bin));
  ASSERT_EQ(r.exit, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("watergraph: compiling pond.json"), std::string::npos) << r.out;
  // It used the installed watergraph, not the build tree's.
  EXPECT_NE(test::readFile(bin + "/CMakeCache.txt").find("watergraph_DIR:PATH=" + prefix), std::string::npos);

  r = eco::sh(shellQuote(bin + "/pond_info"));
  ASSERT_EQ(r.exit, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("pond.glsl330.frag: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("pond.es300.vert: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("#version 300 es"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("uniform p_water (vec3): parameter water = 0.05 0.3 0.35 in [0, 1], an sRGB colour\n"),
            std::string::npos)
      << r.out;
  // PRESET restless: the shimmer speed is 4 (the graph's default is 1.5).
  EXPECT_NE(r.out.find("uniform p_shimmer_speed (float): parameter shimmer_speed = 4 in [0, 10]\n"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("uniform u_time (float): builtin time, set by the renderer before each draw\n"), std::string::npos)
      << r.out;
  // TEXTURES: the built-in normal texture pond samples, written under the manifest's name.
  EXPECT_NE(r.out.find("texture t0_water_normal at binding 1: pond.t0_water_normal.png, "), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(bin + "/shaders/pond.vk450.frag"));  // TARGETS glsl330 es300 only

  // Nothing changed: nothing recompiles.
  r = eco::sh("cmake --build " + shellQuote(bin));
  ASSERT_EQ(r.exit, 0) << r.out << r.err;
  EXPECT_EQ(r.out.find("watergraph: compiling"), std::string::npos) << r.out;

  // Edit the graph: the build recompiles it and the manifest has the new default.
  std::string graph = src + "/graphs/pond.json";
  std::string text = test::readFile(graph);
  size_t at = text.find("[0.05, 0.3, 0.35]");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 17, "[0.25, 0.5, 0.75]");
  test::writeFile(graph, text);
  bumpMtime(graph);
  r = eco::sh("cmake --build " + shellQuote(bin));
  ASSERT_EQ(r.exit, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("watergraph: compiling pond.json"), std::string::npos) << r.out;
  EXPECT_NE(test::readFile(bin + "/shaders/pond.manifest.json").find("0.75"), std::string::npos);

  // Edit the subgraph pond.json imports: the depfile makes the build recompile pond.json.
  std::string sub = src + "/graphs/lib/sky_blend.json";
  text = test::readFile(sub);
  at = text.find("\"default\": 0.02");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 15, "\"default\": 0.0371");
  test::writeFile(sub, text);
  bumpMtime(sub);
  r = eco::sh("cmake --build " + shellQuote(bin));
  ASSERT_EQ(r.exit, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("watergraph: compiling pond.json"), std::string::npos) << r.out;
  EXPECT_NE(test::readFile(bin + "/shaders/pond.glsl330.frag").find("0.0371"), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(Generators, CMakePackage, ::testing::Values(std::string("Ninja"), std::string("Unix Makefiles")),
                         [](const auto& info) { return info.param == "Ninja" ? std::string("Ninja") : std::string("UnixMakefiles"); });

TEST(CMakePackageArguments, BadArgumentsFailAtConfigureTime) {
  // Each case: the call's arguments, and a part of the error CMake must stop with.
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"TARGETS wgsl", "unknown target 'wgsl'"},
      {"TARGETS c-header", "unknown target 'c-header'"},  // removed with --derived-uniforms
      {"PRESET", "PRESET needs a preset name"},
      {"TEXTURES yes", "unknown arguments: yes"},
  };
  eco::TempDir tmp;
  std::string prefix = tmp / "prefix";
  ASSERT_EQ(eco::sh("cmake --install " + shellQuote(buildDir()) + " --prefix " + shellQuote(prefix)).exit, 0);
  for (size_t i = 0; i < cases.size(); ++i) {
    SCOPED_TRACE(cases[i].first);
    const std::string project = tmp / ("p" + std::to_string(i));
    fs::create_directories(project);
    test::writeFile(project + "/CMakeLists.txt",
                    "cmake_minimum_required(VERSION 3.20)\nproject(p NONE)\nfind_package(watergraph CONFIG REQUIRED)\n"
                    "add_custom_target(t)\nwatergraph_add_shaders(TARGET t GRAPHS g.json " +
                        cases[i].first + ")\n");
    auto r = eco::sh("cmake -S " + shellQuote(project) + " -B " + shellQuote(project + "/b") +
                     " -DCMAKE_PREFIX_PATH=" + shellQuote(prefix));
    EXPECT_NE(r.exit, 0);
    EXPECT_NE((r.out + r.err).find(cases[i].second), std::string::npos) << r.out << r.err;
  }
}

}  // namespace
}  // namespace wg
