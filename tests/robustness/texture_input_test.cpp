// Hostile texture inputs (docs/robustness.md): the graph, its textures and its folder are
// under an attacker's control. A texture path must stay inside the graph's folder after
// every symbolic link, hold no control character, and name a PNG whose header declares a
// size within the limits; a PNG that then fails to decode is a graph error (exit 1) at the
// option that names it.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <stb/stb_image_write.h>

#include "png_bytes.h"
#include "codegen/compile.h"
#include "core/graph_io.h"
#include "core/png_header.h"
#include "core/texture_check.h"
#include "nodes/registry.h"
#include "nodes/texture_source.h"
#include "test_support.h"

namespace wg {
namespace {

namespace fs = std::filesystem;

// A real PNG of w x h texels.
// A PNG signature and IHDR declaring w x h, then `rest` (no image data: only the header
// is read before the size is refused).
std::string pngHeaderDeclaring(unsigned w, unsigned h, const std::string& rest = std::string(64, '\0')) {
  std::string s = "\x89PNG\r\n\x1a\n";
  s += std::string("\0\0\0\x0d", 4) + "IHDR";
  for (unsigned v : {w, h})
    for (int shift = 24; shift >= 0; shift -= 8) s += static_cast<char>((v >> shift) & 0xff);
  return s + rest;
}

std::string edgeFoamGraph(const std::string& texture) {
  return test::graphJson("{\"id\": \"f\", \"type\": \"edge_foam\", \"options\": {\"texture\": " +
                             nlohmann::json(texture).dump() + "}, \"inputs\": {\"depth\": 1}}",
                         "\"fragment\": {\"alpha\": \"f.foam\"}");
}

// Loads and resolves graph `text` saved as `dir`/g.json; the diagnostics.
Diagnostics resolveIn(const std::string& dir, const std::string& text) {
  test::writeFile(dir + "/g.json", text);
  Diagnostics diags;
  if (auto graph = loadGraphFile(dir + "/g.json", diags)) buildProgram(*graph, defaultRegistry(), diags);
  return diags;
}

std::string firstError(const Diagnostics& diags) {
  for (const auto& d : diags.sorted())
    if (d.severity == Severity::Error) return formatText(d);
  return "";
}

class TextureInput : public ::testing::Test {
 protected:
  void SetUp() override {
    root = test::makeTempDir("wg_texture_input_");
    dir = root + "/graph";
    outside = root + "/outside";
    fs::create_directories(dir);
    fs::create_directories(outside);
    test::writeFile(outside + "/secret.png", test::pngBytes(2, 2));
  }
  void TearDown() override { fs::remove_all(root); }
  std::string root, dir, outside;
};

TEST_F(TextureInput, AGoodPngInsideTheFolderIsAccepted) {
  test::writeFile(dir + "/foam.png", test::pngBytes(4, 2));
  EXPECT_EQ(firstError(resolveIn(dir, edgeFoamGraph("foam.png"))), "");
  TextureFile file;
  EXPECT_EQ(checkTextureSource("foam.png", dir, &file), "");
  EXPECT_EQ(file.width, 4);
  EXPECT_EQ(file.height, 2);
}

// Found in review: UP.PNG was "not a .png file"; the extension is matched in any case.
TEST_F(TextureInput, AnUpperCaseExtensionIsAPng) {
  test::writeFile(dir + "/UP.PNG", test::pngBytes(2, 2));
  EXPECT_EQ(firstError(resolveIn(dir, edgeFoamGraph("UP.PNG"))), "");
  test::writeFile(dir + "/up.jpg", test::pngBytes(2, 2));
  EXPECT_NE(firstError(resolveIn(dir, edgeFoamGraph("up.jpg"))).find("is not a .png file"), std::string::npos);
}

TEST_F(TextureInput, AFileSymlinkLeadingOutsideIsRefused) {
  fs::create_symlink(outside + "/secret.png", dir + "/foam.png");
  std::string e = firstError(resolveIn(dir, edgeFoamGraph("foam.png")));
  EXPECT_NE(e.find("[WG030]"), std::string::npos) << e;
  EXPECT_NE(e.find("outside the graph's folder"), std::string::npos) << e;
  // compile --textures must not copy the outside file into the output.
  std::string out, err;
  int code = test::runCommandSplit(test::shellQuote(test::watergraphBinary()) + " compile --textures " + dir +
                                       "/g.json -o " + root + "/out",
                                   &out, &err);
  EXPECT_EQ(code, 1) << err;
  EXPECT_TRUE(test::listFilesRecursive(root + "/out").empty());
}

TEST_F(TextureInput, AFolderSymlinkInsideTheTreeLeadingOutsideIsRefused) {
  fs::create_directory_symlink(outside, dir + "/textures");
  std::string e = firstError(resolveIn(dir, edgeFoamGraph("textures/secret.png")));
  EXPECT_NE(e.find("[WG030]"), std::string::npos) << e;
  EXPECT_NE(e.find("outside the graph's folder"), std::string::npos) << e;
}

TEST_F(TextureInput, ASymlinkStayingInsideIsAccepted) {
  fs::create_directories(dir + "/real");
  test::writeFile(dir + "/real/foam.png", test::pngBytes(2, 2));
  fs::create_symlink("real/foam.png", dir + "/foam.png");
  EXPECT_EQ(firstError(resolveIn(dir, edgeFoamGraph("foam.png"))), "");
}

// "README.md\0.png" passed the .png check and the file system opened README.md.
TEST_F(TextureInput, ControlCharactersInPathsAreRefused) {
  test::writeFile(dir + "/README.md", "not a texture");
  test::writeFile(dir + "/a\x01.png", test::pngBytes(2, 2));
  for (std::string path : {std::string("README.md\0.png", 14), std::string("a\x01.png")}) {
    std::string e = firstError(resolveIn(dir, edgeFoamGraph(path)));
    EXPECT_NE(e.find("[WG030]"), std::string::npos) << e;
    EXPECT_NE(e.find("control character"), std::string::npos) << e;
  }
}

// A 260 KB PNG could declare 16384 x 16384 (a gigabyte decoded): the header is checked first.
TEST_F(TextureInput, APngDeclaringMoreThanTheLimitIsRefusedBeforeDecoding) {
  test::writeFile(dir + "/bomb.png", pngHeaderDeclaring(16384, 16384));
  std::string e = firstError(resolveIn(dir, edgeFoamGraph("bomb.png")));
  EXPECT_NE(e.find("[WG030]"), std::string::npos) << e;
  EXPECT_NE(e.find("16384 x 16384"), std::string::npos) << e;
  // At the limit on one side, one past it on the other.
  test::writeFile(dir + "/wide.png", pngHeaderDeclaring(kMaxTextureSide, kMaxTextureSide + 1));
  EXPECT_NE(checkTextureSource("wide.png", dir).find("the limit is 8192"), std::string::npos);
  // The decoder checks the header of the file it opens too (it may have changed since).
  std::string why;
  EXPECT_FALSE(loadTexture("bomb.png", dir, &why));
  EXPECT_NE(why.find("16384"), std::string::npos) << why;
}

TEST_F(TextureInput, TheGraphsTexturesTogetherKeepABudget) {
  // Three distinct files of the largest size: two fit the budget, the third does not.
  std::string nodes;
  for (int i = 0; i < 3; ++i) {
    test::writeFile(dir + "/t" + std::to_string(i) + ".png", pngHeaderDeclaring(kMaxTextureSide, kMaxTextureSide));
    nodes += std::string(i ? "," : "") + "{\"id\": \"f" + std::to_string(i) +
             "\", \"type\": \"edge_foam\", \"options\": {\"texture\": \"t" + std::to_string(i) +
             ".png\"}, \"inputs\": {\"depth\": 1}}";
  }
  // The same file sampled twice counts once.
  nodes += ",{\"id\": \"g\", \"type\": \"edge_foam\", \"options\": {\"texture\": \"t0.png\"}, \"inputs\": {\"depth\": 1}}";
  Diagnostics diags = resolveIn(dir, test::graphJson(nodes, "\"fragment\": {\"alpha\": \"f0.foam\"}"));
  std::vector<std::string> budget;
  for (const auto& d : diags.sorted())
    if (d.message.find("the limit per graph") != std::string::npos) budget.push_back(d.node);
  EXPECT_EQ(budget, std::vector<std::string>{"f2"}) << firstError(diags);
}

TEST_F(TextureInput, AFileThatIsNotAPngIsRefusedAtTheOption) {
  test::writeFile(dir + "/fake.png", "GIF89a not a png");
  std::string e = firstError(resolveIn(dir, edgeFoamGraph("fake.png")));
  EXPECT_NE(e.find("[WG030]"), std::string::npos) << e;
  EXPECT_NE(e.find("not a PNG"), std::string::npos) << e;
}

// A PNG whose header is fine but whose data is not: `compile --textures` reports it as a
// fault of the graph (exit 1, WG030 at the texture option), not as an I/O error (exit 2).
TEST_F(TextureInput, ADecodeFailureIsAGraphErrorAtThePath) {
  std::string good = test::pngBytes(4, 4);
  test::writeFile(dir + "/broken.png", good.substr(0, 33) + std::string(40, 'x'));  // IHDR kept, data garbled
  test::writeFile(dir + "/g.json", edgeFoamGraph("broken.png"));
  std::string out, err;
  int code = test::runCommandSplit(test::shellQuote(test::watergraphBinary()) + " compile --textures " + dir +
                                       "/g.json -o " + root + "/out",
                                   &out, &err);
  EXPECT_EQ(code, 1) << err;
  EXPECT_NE(err.find("g.json:1:"), std::string::npos) << err;
  EXPECT_NE(err.find("error: [WG030] option 'texture' is not usable: cannot decode texture"), std::string::npos) << err;
  EXPECT_TRUE(test::listFilesRecursive(root + "/out").empty());
}

// A PNG whose header is right but whose pixels do not decode (a garbled zlib stream, a
// file cut after its header) fails `validate`, the CI check, not first `render`; a good
// one passes, and a preset's texture is decoded too.
TEST_F(TextureInput, APngThatDoesNotDecodeFailsValidate) {
  std::string good = test::pngBytes(4, 4);
  test::writeFile(dir + "/broken.png", good.substr(0, 33) + std::string(40, 'x'));
  test::writeFile(dir + "/cut.png", pngHeaderDeclaring(4, 4));
  test::writeFile(dir + "/good.png", good);
  const std::string wg = test::shellQuote(test::watergraphBinary());
  for (const char* file : {"broken.png", "cut.png"}) {
    test::writeFile(dir + "/g.json", edgeFoamGraph(file));
    std::string out, err;
    EXPECT_EQ(test::runCommandSplit(wg + " validate " + dir + "/g.json", &out, &err), 1) << file << "\n" << err;
    EXPECT_NE(err.find("error: [WG030] option 'texture' is not usable: cannot decode texture"), std::string::npos) << err;
  }
  test::writeFile(dir + "/g.json", edgeFoamGraph("good.png"));
  std::string out, err;
  EXPECT_EQ(test::runCommandSplit(wg + " validate " + dir + "/g.json", &out, &err), 0) << err;
  // The same broken file set by a preset that is not applied.
  std::string text = edgeFoamGraph("good.png");
  text.insert(text.rfind('}'), R"(, "presets": {"worn": {"f.texture": "broken.png"}})");
  test::writeFile(dir + "/g.json", text);
  EXPECT_EQ(test::runCommandSplit(wg + " validate " + dir + "/g.json", &out, &err), 1) << text << "\n" << err;
  EXPECT_NE(err.find("preset 'worn': option 'texture' is not usable: cannot decode texture"), std::string::npos) << err;
}

// ".." that folds away inside the folder is a path like any other; one that climbs out is
// refused before the file system is asked. Something that exists but is not a file (a
// folder named like a PNG) is said to be that, not to be missing.
TEST_F(TextureInput, AStepBackThatStaysInsideIsAcceptedAndAFolderIsNotAFile) {
  fs::create_directories(dir + "/sub");
  test::writeFile(dir + "/foam.png", test::pngBytes(2, 2));
  EXPECT_EQ(firstError(resolveIn(dir, edgeFoamGraph("sub/../foam.png"))), "");
  std::string e = firstError(resolveIn(dir, edgeFoamGraph("sub/../../outside/secret.png")));
  EXPECT_NE(e.find("leaves the graph's folder"), std::string::npos) << e;
  fs::create_directories(dir + "/folder.png");
  e = firstError(resolveIn(dir, edgeFoamGraph("folder.png")));
  EXPECT_NE(e.find("is not a regular file"), std::string::npos) << e;
  EXPECT_NE(firstError(resolveIn(dir, edgeFoamGraph("missing.png"))).find("does not exist"), std::string::npos);
}

#ifdef WG_HAVE_RUNTIME
// The same PNG through `render` and `check`: both report it as the graph's WG030 at the
// texture option (found when the graph is checked, before the runtime decodes it again),
// exit 1, writing no image: not a bare runtime message.
TEST_F(TextureInput, ADecodeFailureAtRenderTimeIsAGraphErrorAtThePath) {
  std::string good = test::pngBytes(4, 4);
  test::writeFile(dir + "/broken.png", good.substr(0, 33) + std::string(40, 'x'));
  test::writeFile(dir + "/g.json", edgeFoamGraph("broken.png"));
  const std::string wg = test::shellQuote(test::watergraphBinary());
  for (const std::string& command : {" render --size 32x32 " + dir + "/g.json -o " + root + "/frame.png",
                                    " check --size 16x16 --target es300 " + dir + "/g.json"}) {
    std::string out, err;
    int code = test::runCommandSplit(wg + command, &out, &err);
    EXPECT_EQ(code, 1) << command << "\n" << err;
    EXPECT_NE(err.find("g.json:1:"), std::string::npos) << err;
    EXPECT_NE(err.find("error: [WG030] option 'texture' is not usable: cannot decode texture"), std::string::npos)
        << command << "\n" << err;
    EXPECT_NE(err.find("(node 'f'"), std::string::npos) << err;
  }
  EXPECT_FALSE(fs::exists(root + "/frame.png"));
}
#endif

// The texture fuzz target's find (tests/fuzz/corpus/texture/idat_declares_1.9GB): a 2 x 2
// PNG of 71 bytes whose IDAT chunk declares 1,912,649,216 bytes. The decoder grew its
// buffer towards that size before finding the file short (5.6 s under ASan). Refused now
// from the chunk lengths, before the decoder sees the bytes.
std::string pngWithChunkPastTheEnd() {
  std::string png = test::pngBytes(2, 2);
  std::size_t idat = png.find("IDAT") - 4;
  const char declared[4] = {0x72, 0x00, 0x00, 0x00};  // 1,912,602,624
  png.replace(idat, 4, declared, 4);
  return png;
}

TEST_F(TextureInput, AChunkDeclaringMoreBytesThanTheFileIsRefusedBeforeDecoding) {
  test::writeFile(dir + "/short.png", pngWithChunkPastTheEnd());
  std::string error;
  EXPECT_FALSE(loadTexture("short.png", dir, &error));
  EXPECT_NE(error.find("cannot decode texture"), std::string::npos) << error;
  EXPECT_NE(error.find("its IDAT chunk at byte 33 declares 1912602624 bytes of data; the file has"), std::string::npos)
      << error;
}

TEST(PngChunks, EachChunkMustFitInsideTheFileUpToIend) {
  auto check = [](const std::string& b) {
    return checkPngChunks(reinterpret_cast<const unsigned char*>(b.data()), b.size());
  };
  std::string good = test::pngBytes(3, 2);
  EXPECT_EQ(check(good), "");
  EXPECT_EQ(check(good + "trailing bytes after IEND"), "");
  EXPECT_NE(check(pngWithChunkPastTheEnd()).find("IDAT chunk at byte 33"), std::string::npos);
  std::size_t iend = good.find("IEND") - 4;
  EXPECT_EQ(check(good.substr(0, iend)), "it has no IEND chunk");
  EXPECT_EQ(check(good.substr(0, iend + 5)), "it ends inside a chunk's header at byte " + std::to_string(iend));
  std::string huge = good;  // a length over 2^31 - 1, which the specification forbids
  huge.replace(iend, 4, std::string("\x80\0\0\0", 4));
  EXPECT_NE(check(huge).find("IEND chunk"), std::string::npos);
}

TEST(PngHeader, ReadsTheDeclaredSize) {
  std::string h = pngHeaderDeclaring(640, 480);
  PngSize size;
  EXPECT_EQ(readPngSize(reinterpret_cast<const unsigned char*>(h.data()), h.size(), &size), "");
  EXPECT_EQ(size.width, 640);
  EXPECT_EQ(size.height, 480);
  EXPECT_NE(readPngSize(reinterpret_cast<const unsigned char*>(h.data()), 20, &size), "");  // too short
  std::string bad = h;
  bad[12] = 'X';  // not IHDR
  EXPECT_NE(readPngSize(reinterpret_cast<const unsigned char*>(bad.data()), bad.size(), &size), "");
  std::string empty = pngHeaderDeclaring(0, 5);
  EXPECT_NE(readPngSize(reinterpret_cast<const unsigned char*>(empty.data()), empty.size(), &size), "");
}

}  // namespace
}  // namespace wg
