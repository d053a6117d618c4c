// Check-then-read races on the files watergraph reads (docs/robustness.md, "Inputs swapped
// while they are read"). The folder of a graph may be shared with someone hostile, who swaps
// an import or a texture for a symbolic link between the moment its path is checked and the
// moment it is read. Every input is opened once and checked on that open file
// (core/file_read.h): whatever the timing, nothing from outside the folder is ever returned.
// The swap is one atomic rename (RENAME_EXCHANGE) in a tight loop on another thread. (With
// the checks of the opened file removed, the import test found the outside file in 4 of 5
// runs on a busy 2-core machine, the texture test in every run.)
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <fcntl.h>
#include <filesystem>
#include <string>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

#include "core/file_read.h"
#include "core/graph_io.h"
#include "core/png_decode.h"
#include "core/texture_check.h"
#include "png_bytes.h"
#include "test_support.h"

namespace wg {
namespace {

namespace fs = std::filesystem;

// Exchanges two names atomically, again and again, until stopped.
class Swapper {
 public:
  Swapper(std::string a, std::string b) : a_(std::move(a)), b_(std::move(b)) {
    thread_ = std::thread([this] {
      while (!stop_)
        if (::renameat2(AT_FDCWD, a_.c_str(), AT_FDCWD, b_.c_str(), RENAME_EXCHANGE) == 0) ++swaps_;
    });
  }
  ~Swapper() {
    stop_ = true;
    thread_.join();
  }
  long swaps() const { return swaps_; }

 private:
  std::string a_, b_;
  std::atomic<bool> stop_{false};
  std::atomic<long> swaps_{0};
  std::thread thread_;
};

std::string leafGraph(const std::string& name) {
  return "{\"version\": 1, \"name\": \"" + name +
         "\", \"interface\": {\"outputs\": {\"v\": {\"type\": \"float\", \"source\": \"n.out\"}}},"
         " \"nodes\": [{\"id\": \"n\", \"type\": \"saturate\", \"inputs\": {\"x\": 0.5}}]}";
}

class FileRace : public ::testing::Test {
 protected:
  void SetUp() override {
    root = test::makeTempDir("wg_file_race_");
    dir = root + "/graph";
    outside = root + "/outside";
    fs::create_directories(dir);
    fs::create_directories(outside);
  }
  void TearDown() override { fs::remove_all(root); }
  std::string root, dir, outside;
};

// The review's attack: lib.json is a file inside the folder, then a link to a graph outside
// it. The importer checked the name and read it again by name: 24 of 8,312 loads returned
// the outside graph.
TEST_F(FileRace, AnImportSwappedForALinkNeverLoadsTheOutsideFile) {
  test::writeFile(outside + "/secret.json", leafGraph("secret"));
  test::writeFile(dir + "/lib.json", leafGraph("inside"));
  fs::create_symlink("../outside/secret.json", dir + "/lib.swap");
  test::writeFile(dir + "/top.json",
                  "{\"version\": 1, \"name\": \"top\", \"imports\": {\"lib\": \"lib.json\"},"
                  " \"nodes\": [{\"id\": \"l\", \"type\": \"lib\"}], \"outputs\": {\"fragment\": {\"alpha\": \"l.v\"}}}");
  int loaded = 0, refused = 0;
  {
    Swapper swapper(dir + "/lib.json", dir + "/lib.swap");
    // As many loads as fit in a few seconds: the swap lands between the check and the read
    // only now and then, more rarely when the machine is busy.
    auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < 100000 && std::chrono::steady_clock::now() - start < std::chrono::seconds(3); ++i) {
      Diagnostics diags;
      auto graph = loadGraphFile(dir + "/top.json", diags);
      if (!graph) {
        ++refused;
        continue;
      }
      ASSERT_EQ(graph->imports.size(), 1u);
      ASSERT_TRUE(graph->imports[0].graph);
      ASSERT_EQ(graph->imports[0].graph->name, "inside") << "load " << i << " read the file outside the folder";
      ++loaded;
    }
    EXPECT_GT(swapper.swaps(), 100);
  }
  // Both outcomes happen: the race was really run.
  EXPECT_GT(loaded, 0);
  EXPECT_GT(refused, 0);
}

// A texture's folder swapped for a link to a folder outside, between the check of the path
// and the decoding of the file: the decoder insists on the very file that was checked.
TEST_F(FileRace, ATextureFolderSwappedForALinkNeverDecodesTheOutsideFile) {
  fs::create_directories(dir + "/tex");
  test::writeFile(dir + "/tex/foam.png", test::pngBytes(2, 2, 90));
  test::writeFile(outside + "/foam.png", test::pngBytes(3, 5, 90));
  fs::create_directory_symlink("../outside", dir + "/tex.swap");
  int decoded = 0, refused = 0;
  {
    Swapper swapper(dir + "/tex", dir + "/tex.swap");
    for (int i = 0; i < 20000; ++i) {
      TextureFile file;
      if (!checkTextureSource("tex/foam.png", dir, &file).empty()) {
        ++refused;
        continue;
      }
      ASSERT_EQ(file.width, 2) << "the header of the outside file was read";
      DecodedPng png;
      std::string why;
      if (!decodePng(file.realPath, &png, &why)) {
        ++refused;
        continue;
      }
      ASSERT_EQ(png.width, 2) << "try " << i << " decoded the file outside the folder";
      ++decoded;
    }
  }
  EXPECT_GT(decoded, 0);
  EXPECT_GT(refused, 0);
}

TEST_F(FileRace, TheReaderChecksTheOpenedFile) {
  test::writeFile(dir + "/a.txt", "inside");
  test::writeFile(outside + "/b.txt", "outside");
  fs::create_symlink("../outside/b.txt", dir + "/link.txt");
  const std::string folder = fs::canonical(dir).string();
  FileReadRule rule;
  rule.maxBytes = 100;
  rule.insideFolder = folder;
  FileReadFailure failure;
  auto a = readFileChecked(dir + "/a.txt", rule, &failure);
  ASSERT_TRUE(a);
  EXPECT_EQ(a->bytes, "inside");
  EXPECT_EQ(a->realPath, folder + "/a.txt");
  EXPECT_FALSE(readFileChecked(dir + "/link.txt", rule, &failure));
  EXPECT_EQ(failure.kind, FileReadFailure::Kind::Outside);
  // mustResolveTo: exactly that file.
  FileReadRule exact;
  exact.maxBytes = 100;
  exact.mustResolveTo = folder + "/a.txt";
  EXPECT_TRUE(readFileChecked(dir + "/a.txt", exact, &failure));
  EXPECT_FALSE(readFileChecked(outside + "/b.txt", exact, &failure));
  // Size: the limit is held on the bytes read, and a header read stops early.
  rule.maxBytes = 3;
  EXPECT_FALSE(readFileChecked(dir + "/a.txt", rule, &failure));
  EXPECT_EQ(failure.kind, FileReadFailure::Kind::TooLarge);
  rule.readAtMost = 2;
  rule.maxBytes = 100;
  auto head = readFileChecked(dir + "/a.txt", rule, &failure);
  ASSERT_TRUE(head);
  EXPECT_EQ(head->bytes, "in");
  // A FIFO is refused without blocking when only regular files are read; a folder always.
  ASSERT_EQ(::mkfifo((dir + "/fifo").c_str(), 0600), 0);
  FileReadRule regular;
  regular.maxBytes = 100;
  EXPECT_FALSE(readFileChecked(dir + "/fifo", regular, &failure));
  EXPECT_EQ(failure.kind, FileReadFailure::Kind::NotRegular);
  EXPECT_FALSE(readFileChecked(dir, regular, &failure));
  regular.regularOnly = false;
  EXPECT_FALSE(readFileChecked(dir, regular, &failure));
  EXPECT_EQ(failure.why(), std::strerror(EISDIR));
}

}  // namespace
}  // namespace wg
