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
