#include "codegen/temp_file.h"

#include <cerrno>
#include <fcntl.h>
#include <random>
#include <unistd.h>

namespace wg {
namespace {

std::string randomSuffix(std::mt19937_64& rng) {
  static const char letters[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  std::string s;
  for (int i = 0; i < 8; ++i) s += letters[rng() % (sizeof letters - 1)];
  return s;
}

bool writeAll(int fd, std::string_view contents) {
  while (!contents.empty()) {
    ssize_t n = ::write(fd, contents.data(), contents.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    contents.remove_prefix(static_cast<size_t>(n));
  }
  return true;
}

}  // namespace

std::optional<std::string> writeTemporaryBeside(const std::filesystem::path& target, std::string_view contents,
                                                int* error) {
  std::random_device seed;
  std::mt19937_64 rng((static_cast<unsigned long long>(seed()) << 32) ^ seed());
  std::filesystem::path dir = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
  // Names taken by someone else (a file or a planted link) are skipped; a hundred taken in a
  // row means something else is wrong.
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::string path = (dir / ("." + target.filename().string() + "." + randomSuffix(rng) + ".tmp")).string();
    int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd < 0) {
      if (errno == EEXIST) continue;
      *error = errno;
      return std::nullopt;
    }
    bool ok = writeAll(fd, contents);
    int err = errno;
    if (::close(fd) != 0 && ok) {
      ok = false;
      err = errno;
    }
    if (!ok) {
      ::unlink(path.c_str());
      *error = err ? err : EIO;
      return std::nullopt;
    }
    return path;
  }
  *error = EEXIST;
  return std::nullopt;
}

}  // namespace wg
