// The output folder may be shared with someone hostile, who plants a symbolic link under
// the name a temporary file will have: writing must never follow it (docs/robustness.md).
// Temporaries used to be ".NAME.tmp<pid>" opened with std::ofstream, which followed the
// link, overwrote its target, and renamed the link into place as the output.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

#include "codegen/output_files.h"
#include "codegen/temp_file.h"
#include "test_support.h"

namespace wg {
namespace {

namespace fs = std::filesystem;

class OutputRace : public ::testing::Test {
 protected:
  void SetUp() override {
    root = test::makeTempDir("wg_output_race_");
    out = root + "/out";
    fs::create_directories(out);
    victim = root + "/victim.txt";
    test::writeFile(victim, "precious");
  }
  void TearDown() override { fs::remove_all(root); }

  // Links at the names the old code used (this process's pid), and at a few more guesses.
  void plantLinks(const std::string& name) {
    for (const std::string& suffix : {".tmp" + std::to_string(getpid()), "." + std::to_string(getpid()) + ".tmp"})
      fs::create_symlink(victim, out + "/." + name + suffix);
  }

  void expectVictimUntouchedAndRegular(const std::string& written, const std::string& contents) {
    EXPECT_EQ(test::readFile(victim), "precious");
    struct stat st {};
    ASSERT_EQ(::lstat(written.c_str(), &st), 0);
    EXPECT_TRUE(S_ISREG(st.st_mode)) << written << " is not a regular file";
    EXPECT_EQ(test::readFile(written), contents);
  }
  std::string root, out, victim;
};

TEST_F(OutputRace, CompileOutputNeverFollowsAPlantedLink) {
  plantLinks("lake.glsl330.frag");
  Diagnostics diags;
  ASSERT_TRUE(writeOutputFiles(out, {{"lake.glsl330.frag", "void main() {}\n"}}, diags));
  expectVictimUntouchedAndRegular(out + "/lake.glsl330.frag", "void main() {}\n");
}

TEST_F(OutputRace, FmtNeverFollowsAPlantedLink) {
  test::writeFile(out + "/g.json", "{}");
  plantLinks("g.json");
  Diagnostics diags;
  ASSERT_TRUE(writeFileAtomically(out + "/g.json", "{\"formatted\": true}\n", diags));
  expectVictimUntouchedAndRegular(out + "/g.json", "{\"formatted\": true}\n");
}

// A link planted at the output's own name (not at a temporary's) is replaced by the new
// file, never written through: `--depfile out/x.d` and `render -o r.png` wrote into the
// link's target (the writer resolved the link and replaced the file it named).
TEST_F(OutputRace, ALinkAtTheOutputNameIsReplacedNotFollowed) {
  fs::create_symlink(victim, out + "/x.d");
  Diagnostics diags;
  ASSERT_TRUE(writeFileAtomically(out + "/x.d", "new\n", diags));
  expectVictimUntouchedAndRegular(out + "/x.d", "new\n");
  // A dangling link too (it would have created the file it names).
  fs::create_symlink(root + "/created-through-link", out + "/y.d");
  ASSERT_TRUE(writeFileAtomically(out + "/y.d", "y\n", diags));
  EXPECT_FALSE(fs::exists(root + "/created-through-link"));
  // The up-front check accepts a link: it will be replaced.
  EXPECT_TRUE(checkWritable(out + "/x.d", diags));
  // An in-place rewrite (fmt, tune --write-preset) resolves the user's own link first: the
  // link stays and its file is rewritten.
  fs::create_symlink("x.d", out + "/mine.d");
  ASSERT_TRUE(writeFileAtomically(realPathForRewrite(out + "/mine.d"), "rewritten\n", diags));
  EXPECT_TRUE(fs::is_symlink(out + "/mine.d"));
  EXPECT_EQ(test::readFile(out + "/x.d"), "rewritten\n");
  EXPECT_FALSE(diags.hasErrors());
}

// Every command's output, through the command line: a link planted at each output path.
TEST_F(OutputRace, NoCommandWritesThroughALinkAtItsOutput) {
  const std::string wg = test::shellQuote(test::watergraphBinary());
  const std::string lake = test::shellQuote(test::sourcePath("graphs/lake.json"));
  struct Case {
    std::string name, command;
  };
  std::vector<Case> cases = {
      {"shaders.d", "compile " + lake + " --target glsl330 -o " + out + "/shaders --depfile " + out + "/shaders.d"},
      {"schema.json", "schema -o " + out + "/schema.json"},
#ifdef WG_HAVE_RUNTIME
      {"scene.json", "scene -o " + out + "/scene.json"},
      {"r.png", "render " + lake + " --size 16x9 -o " + out + "/r.png"},
#endif
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.command);
    fs::create_symlink(victim, out + "/" + c.name);
    std::string output;
    int code = test::runCommand(wg + " " + c.command + " 2>&1", &output);
    EXPECT_EQ(code, 0) << output;
    EXPECT_EQ(test::readFile(victim), "precious");
    EXPECT_FALSE(fs::is_symlink(out + "/" + c.name));
    EXPECT_TRUE(fs::is_regular_file(out + "/" + c.name));
  }
}

TEST_F(OutputRace, TemporariesAreNewFilesUnderUnpredictableNames) {
  int err = 0;
  auto a = writeTemporaryBeside(out + "/x.frag", "a", &err);
  auto b = writeTemporaryBeside(out + "/x.frag", "b", &err);
  ASSERT_TRUE(a && b) << err;
  EXPECT_NE(*a, *b);
  EXPECT_EQ(fs::path(*a).parent_path(), fs::path(out));
  EXPECT_EQ(test::readFile(*a), "a");
  // The new file has the usual mode less the umask, not mkstemp's 0600.
  mode_t mask = ::umask(0);
  ::umask(mask);
  struct stat st {};
  ASSERT_EQ(::stat(a->c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0666 & ~mask);
  // Nothing is left behind when the folder is not there.
  EXPECT_FALSE(writeTemporaryBeside(root + "/missing/x.frag", "c", &err));
  EXPECT_EQ(err, ENOENT);
}

}  // namespace
}  // namespace wg
