// Hostile file names, output paths and option values through the command line (issue 40;
// docs/robustness.md): a graph named with bytes that are not UTF-8, strings that would act
// on a terminal, output paths that cannot be written (found before any work), empty option
// values and list entries, a PNG whose CRC does not match.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <sys/stat.h>

#include <nlohmann/json.hpp>
#include <stb/stb_image_write.h>

#include "png_bytes.h"
#include "core/png_header.h"
#include "core/shown_text.h"
#include "test_support.h"

namespace wg {
namespace {

namespace fs = std::filesystem;
using test::shellQuote;

class HostileFilesCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = test::makeTempDir("wg_hostile_files_");
    lake = test::sourcePath("graphs/lake.json");
  }
  void TearDown() override { fs::remove_all(dir); }
  test::CmdResult wg(const std::string& args) { return test::runWatergraph(args); }
  std::string dir, lake;
};

bool holdsTerminalControl(const std::string& text) {
  for (char c : text) {
    auto u = static_cast<unsigned char>(c);
    if ((u < 0x20 && c != '\n' && c != '\t') || u == 0x7f) return true;
  }
  return false;
}

// --- file names that are not UTF-8 ---------------------------------------------------------

// `\xff\xfe\x01z.json` gave "internal error: [json.exception.type_error.316]" for compile,
// validate and render, and --diagnostics-format json printed nothing.
TEST_F(HostileFilesCli, AGraphNamedWithBytesThatAreNotUtf8) {
  const std::string name = dir + "/\xff\xfe\x01z.json";
  fs::copy_file(lake, name);
  for (const std::string& command :
       {std::string("validate"), std::string("validate --diagnostics-format json"), "compile -o " + shellQuote(dir + "/out")}) {
    SCOPED_TRACE(command);
    auto r = wg(command + " " + shellQuote(name));
    EXPECT_EQ(r.exit, 0) << r.out << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  }
  // The output files are named with '_' for each such byte, and the manifest names them.
  auto manifest = nlohmann::json::parse(test::readFile(dir + "/out/__\x01z.manifest.json"));
  EXPECT_NE(manifest.dump().find("__\\u0001z.glsl330.frag"), std::string::npos);
  // A graph error in such a file: JSON that parses, naming the file with \xNN escapes; the
  // text diagnostics escape it the same way.
  test::writeFile(name, "{");
  auto r = wg("validate --diagnostics-format json " + shellQuote(name));
  EXPECT_EQ(r.exit, 1) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["diagnostics"][0]["file"], dir + "/\\xff\\xfe\x01z.json");
  r = wg("validate --diagnostics-format sarif " + shellQuote(name));
  EXPECT_EQ(r.exit, 1) << r.err;
  EXPECT_TRUE(nlohmann::json::accept(r.out)) << r.out;
  r = wg("validate " + shellQuote(name));
  EXPECT_EQ(r.exit, 1);
  EXPECT_NE(r.err.find(dir + "/\\xff\\xfe\\x01z.json:1:2: error: [WG001]"), std::string::npos) << r.err;
  EXPECT_FALSE(holdsTerminalControl(r.err)) << r.err;
  EXPECT_EQ(r.err.find('\xff'), std::string::npos);
  // A message that names the file (it cannot be read) escapes it too.
  r = wg("validate --diagnostics-format json " + shellQuote(dir + "/missing\xff.json"));
  EXPECT_EQ(r.exit, 2);
  EXPECT_TRUE(nlohmann::json::accept(r.out)) << r.out;
#ifdef WG_HAVE_RUNTIME
  fs::copy_file(lake, name, fs::copy_options::overwrite_existing);
  r = wg("render " + shellQuote(name) + " --size 16x9 -o " + shellQuote(dir + "/r.png") + " --diagnostics-format json");
  EXPECT_EQ(r.exit, 0) << r.out << r.err;
#endif
}

TEST(ShownText, EscapesWhatATerminalWouldActOn) {
  EXPECT_EQ(escapedForTerminal("a\x1b]0;title\x07" "b\n\t\r"), "a\\x1b]0;title\\x07b\\n\\t\\r");
  EXPECT_EQ(escapedForTerminal("caf\xc3\xa9 \xe2\x80\x94"), "caf\xc3\xa9 \xe2\x80\x94");  // UTF-8 stays
  EXPECT_EQ(escapedForTerminal("\xc2\x9b" "2J"), "\\xc2\\x9b2J");                     // C1 CSI
  EXPECT_EQ(escapedForTerminal("\xff\xfe"), "\\xff\\xfe");
  EXPECT_EQ(escapedForTerminal("\xe2\x80"), "\\xe2\\x80");  // a sequence cut short
  EXPECT_EQ(escapedForTerminal("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // a UTF-16 surrogate
  EXPECT_EQ(validUtf8("a\xff\x01\xc3\xa9"), "a\\xff\x01\xc3\xa9");
  EXPECT_EQ(escapedKeepingLines("a\nb\x1b\tc"), "a\nb\\x1b\tc");
}

// --- terminal escapes -----------------------------------------------------------------------

// `nodes --graph` printed an imported file's description with ESC and BEL raw (clear the
// screen, set the window title); `compile --verbose --summary` printed a file name raw.
TEST_F(HostileFilesCli, StringsFromFilesAndArgumentsReachTheTerminalEscaped) {
  test::writeFile(dir + "/lib.json",
                  "{\"version\": 1, \"name\": \"lib\", \"interface\": {\"description\": \"\\u001b]0;pwned\\u0007\\u001b[2J\","
                  " \"outputs\": {\"v\": {\"type\": \"float\", \"source\": \"n.out\", \"description\": \"\\u009b31m\"}}},"
                  " \"nodes\": [{\"id\": \"n\", \"type\": \"saturate\", \"inputs\": {\"x\": 0.5}}]}");
  auto r = wg("nodes --graph " + shellQuote(dir + "/lib.json"));
  EXPECT_EQ(r.exit, 0) << r.err;
  EXPECT_FALSE(holdsTerminalControl(r.out)) << r.out;
  EXPECT_NE(r.out.find("\\x1b]0;pwned\\x07\\x1b[2J"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("\xc2\x9b"), std::string::npos) << r.out;
  const std::string named = dir + "/e\x1b[31mred\x07.json";
  fs::copy_file(lake, named);
  r = wg("compile --verbose --summary --target glsl330 -o " + shellQuote(dir + "/out") + " " + shellQuote(named));
  EXPECT_EQ(r.exit, 0) << r.err;
  EXPECT_FALSE(holdsTerminalControl(r.out + r.err)) << r.out << r.err;
  EXPECT_NE(r.out.find("e\\x1b[31mred\\x07"), std::string::npos) << r.out;
  // A usage error quoting the argument.
  r = wg("compile " + shellQuote(lake) + " -o " + shellQuote(dir + "/o2") + " --target " + shellQuote("x\x1b[2J"));
  EXPECT_EQ(r.exit, 2);
  EXPECT_FALSE(holdsTerminalControl(r.out + r.err)) << r.err;
}

// --- output paths checked before any work ---------------------------------------------------

// `tune --plot`, `bench --markdown`, `check --error-map`, `render -o` did all the work, then
// failed (some without a code). Every output path is checked first: WG051 and exit 2, and
// nothing is printed on stdout (no work was done).
TEST_F(HostileFilesCli, AnOutputPathThatCannotBeWrittenFailsBeforeAnyWork) {
  test::writeFile(dir + "/afile", "x");
  const std::string bad = dir + "/afile/x.out";
  std::vector<std::string> commands = {
      "compile " + shellQuote(lake) + " -o " + shellQuote(dir + "/out") + " --depfile " + shellQuote(bad),
      "schema -o " + shellQuote(bad),
#ifdef WG_HAVE_RUNTIME
      "render " + shellQuote(lake) + " --size 16x9 -o " + shellQuote(bad),
      "check " + shellQuote(lake) + " --target glsl330 --size 16x16 --error-map " + shellQuote(bad),
      "tune " + shellQuote(lake) + " --min-psnr 40 --size 16x9 --runs 1 --plot " + shellQuote(bad),
      "bench --size 8x8 --runs 1 --markdown " + shellQuote(bad),
      "bench --size 8x8 --runs 1 --plot " + shellQuote(bad),
      "scene -o " + shellQuote(bad),
      "probe --node pow --sweep x=0:1:2 --table " + shellQuote(bad),
#endif
  };
  for (const auto& command : commands) {
    SCOPED_TRACE(command);
    auto r = wg(command);
    EXPECT_EQ(r.exit, 2) << r.out << r.err;
    EXPECT_NE(r.err.find(bad + ": error: [WG051] cannot write: " + dir + "/afile is not a folder"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
  }
  EXPECT_FALSE(fs::exists(dir + "/out"));
  // An empty path, and a folder where the file would go.
  fs::create_directories(dir + "/folder.png");
  for (const std::string& output : {std::string("''"), shellQuote(dir + "/folder.png"), shellQuote(dir + "/sub/")}) {
    auto r = wg("schema -o " + output);
    EXPECT_EQ(r.exit, 2) << output << ": " << r.err;
  }
#ifdef WG_HAVE_RUNTIME
  // tune --write-preset rewrites the graph: a read-only graph is refused before tuning.
  fs::copy_file(lake, dir + "/ro.json");
  fs::permissions(dir + "/ro.json", fs::perms::owner_read);
  auto r = wg("tune " + shellQuote(dir + "/ro.json") + " --min-psnr 40 --size 16x9 --runs 1 --write-preset p");
  EXPECT_EQ(r.exit, 2) << r.err;
  EXPECT_NE(r.err.find("[WG051] cannot replace: the file is read-only"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
#endif
}

// --- consistency of option values -----------------------------------------------------------

// `--preset ''` was taken as no preset; `tune --cameras ''` and `--cameras above,` were
// accepted where `--target glsl330,` is refused; `bench --family nosuch` exited 1 with no
// code. Every option refuses an empty value, and every list an empty entry.
TEST_F(HostileFilesCli, EmptyValuesAndEmptyListEntriesAreUsageErrors) {
  const std::string out = shellQuote(dir + "/out");
  std::vector<std::string> commands = {
      "compile " + shellQuote(lake) + " -o " + out + " --preset ''",
      "validate " + shellQuote(lake) + " --preset ''",
      "compile " + shellQuote(lake) + " -o ''",
      "nodes --graph ''",
#ifdef WG_HAVE_RUNTIME
      "render " + shellQuote(lake) + " -o " + shellQuote(dir + "/r.png") + " --preset ''",
      "check " + shellQuote(lake) + " --preset ''",
      "bench " + shellQuote(lake) + " --preset ''",
      "tune " + shellQuote(lake) + " --min-psnr 40 --cameras ''",
      "tune " + shellQuote(lake) + " --min-psnr 40 --cameras above,",
      "tune " + shellQuote(lake) + " --min-psnr 40 --cameras ,above",
      "tune " + shellQuote(lake) + " --min-psnr 40 --times 1,",
      "bench --family ''",
#endif
  };
  for (const auto& command : commands) {
    SCOPED_TRACE(command);
    auto r = wg(command);
    EXPECT_EQ(r.exit, 2) << r.out << r.err;
    EXPECT_TRUE(r.err.find("the value is empty") != std::string::npos || r.err.find("has an empty entry") != std::string::npos)
        << r.err;
    EXPECT_EQ(test::splitLines(r.err).size(), 1u) << r.err;
  }
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

#ifdef WG_HAVE_RUNTIME
TEST_F(HostileFilesCli, AFamilyThatDoesNotExistIsAUsageError) {
  auto r = wg("bench --config " + shellQuote(test::sourcePath("bench/variants.json")) + " --size 8x8 --runs 1 --family nosuch");
  EXPECT_EQ(r.exit, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("no family 'nosuch'"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
}
#endif

// --- PNG CRCs ------------------------------------------------------------------------------

// stb_image does not check CRCs: a PNG with a corrupt IDAT decoded into whatever the bytes
// say. Every chunk's CRC is checked before decoding.
TEST(PngCrc, AChunkWhoseCrcDoesNotMatchIsRefused) {
  auto check = [](const std::string& b) { return checkPngChunks(reinterpret_cast<const unsigned char*>(b.data()), b.size()); };
  const std::string good = test::pngBytes(4, 4, 120);
  ASSERT_EQ(check(good), "");
  std::size_t idat = good.find("IDAT") - 4;
  std::size_t length = (static_cast<unsigned char>(good[idat + 2]) << 8) | static_cast<unsigned char>(good[idat + 3]);
  std::string badCrc = good;
  badCrc[idat + 8 + length] ^= 0x01;  // the CRC's first byte
  EXPECT_EQ(check(badCrc), "its IDAT chunk at byte " + std::to_string(idat) + " has a wrong CRC (the file is corrupt)");
  std::string badData = good;
  badData[idat + 8] ^= 0x40;  // a data byte: the CRC no longer matches
  EXPECT_NE(check(badData).find("IDAT chunk"), std::string::npos);
  std::string badHeader = good;
  badHeader[16 + 3] ^= 0x01;  // IHDR's width
  EXPECT_NE(check(badHeader).find("IHDR chunk at byte 8 has a wrong CRC"), std::string::npos);
}

}  // namespace
}  // namespace wg
