// examples/gl-host is a host of someone else's: a standalone EGL + OpenGL program that links
// no watergraph library and draws a compiled graph from the files alone (shaders, manifest,
// node textures, `watergraph scene`), following docs/integration.md. The test builds it as a
// user would, runs it on two example graphs — one sampling its own texture with time, one
// displacing the grid with time-phased Gerstner waves — and compares its picture with
// `watergraph render` of the same graph, water alone over black, through the same
// transform (clamp and sRGB): the contract holds if the pictures agree.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "eco_support.h"
#include "runtime/image.h"

namespace wg::eco {
namespace {

using test::shellQuote;

// Same driver, same shaders: the two differ only where the host's float arithmetic for the
// matrices and phases rounds otherwise than the runtime's (a last bit of a vertex position
// moves an edge pixel). Measured 60+ dB; 40 is the bar for "the contract holds".
constexpr double kMinPsnrDb = 40.0;

TEST(GlHost, AStandaloneHostDrawsWhatRenderDraws) {
  TempDir tmp;
  const std::string build = tmp / "gl-host-build";
  const std::string generator = haveTool("ninja") ? " -G Ninja" : "";
  auto r = sh("cmake -S " + shellQuote(test::sourcePath("examples/gl-host")) + " -B " + shellQuote(build) + generator +
              " -DCMAKE_BUILD_TYPE=Release");
  ASSERT_EQ(r.exit, 0) << r.out << r.err;
  r = sh("cmake --build " + shellQuote(build));
  ASSERT_EQ(r.exit, 0) << r.out << r.err;

  const std::string out = tmp / "out";
  r = wgRun("compile " + shellQuote(test::sourcePath("graphs/lagoon.json")) + " " +
            shellQuote(test::sourcePath("graphs/topdown.json")) + " -o " + shellQuote(out) + " --target glsl330 --textures");
  ASSERT_EQ(r.exit, 0) << r.err;
  r = wgRun("scene -o " + shellQuote(out + "/scene.json"));
  ASSERT_EQ(r.exit, 0) << r.err;
  for (const std::string graph : {"lagoon", "topdown"}) {
    SCOPED_TRACE(graph);
    const std::string host = tmp / (graph + ".host.png"), render = tmp / (graph + ".render.png");
    r = sh(shellQuote(build + "/gl_host") + " " + shellQuote(out + "/" + graph + ".manifest.json") + " " +
           shellQuote(out + "/scene.json") + " --camera above --time 3.5 --size 320x180 -o " + shellQuote(host));
    ASSERT_EQ(r.exit, 0) << r.out << r.err;
    r = wgRun("render " + shellQuote(test::sourcePath("graphs/" + graph + ".json")) + " -o " + shellQuote(render) +
              " --scene none --tonemap none --exposure 0 --camera above --time 3.5 --size 320x180");
    ASSERT_EQ(r.exit, 0) << r.err;
    rt::Image a = rt::readPng(host), b = rt::readPng(render);
    ASSERT_EQ(a.rgba8.size(), b.rgba8.size());
    size_t water = 0;  // the comparison must reach the water, not only the black around it
    for (size_t i = 0; i < a.rgba8.size(); i += 4) water += (a.rgba8[i] | a.rgba8[i + 1] | a.rgba8[i + 2]) != 0;
    EXPECT_GT(water, a.rgba8.size() / 4 / 3) << "less than a third of the picture is water";
    const double psnr = rt::psnrRgb8(a, b);
    std::printf("gl-host %s against render: %.1f dB\n", graph.c_str(), psnr);
    EXPECT_GE(psnr, kMinPsnrDb);
  }
}

}  // namespace
}  // namespace wg::eco
