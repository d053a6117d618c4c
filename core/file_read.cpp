#include "core/file_read.h"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

namespace wg {
namespace {

class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

// Where the opened file really is. /proc names the descriptor's own file; without /proc,
// the canonical path counts only when it names the very file that is open (same device and
// inode), so a swap between the open and the look-up is still caught.
std::string realPathOf(int fd, const std::string& path, const struct stat& opened) {
  std::string viaProc = realPathOfDescriptor(fd);
  if (!viaProc.empty()) return viaProc;
  std::error_code ec;
  std::string canonical = std::filesystem::canonical(path, ec).string();
  struct stat st {};
  if (ec || ::stat(canonical.c_str(), &st) != 0 || st.st_dev != opened.st_dev || st.st_ino != opened.st_ino) return "";
  return canonical;
}

}  // namespace

std::string FileReadFailure::why() const {
  switch (kind) {
    case Kind::Open:
    case Kind::Read: return std::strerror(error ? error : EIO);
    case Kind::NotRegular: return "it is not a regular file";
    case Kind::TooLarge: return "it is larger than the limit";
    case Kind::Outside: return "it lies outside the folder it must be in";
  }
  return "cannot be read";
}

std::string realPathOfDescriptor(int fd) {
  char buf[PATH_MAX + 1];
  std::string link = "/proc/self/fd/" + std::to_string(fd);
  ssize_t n = ::readlink(link.c_str(), buf, PATH_MAX);
  if (n <= 0 || buf[0] != '/') return "";  // no /proc, or "pipe:[123]"
  std::string real(buf, static_cast<std::size_t>(n));
  // A file removed while open reads "/x (deleted)": not a path that can be checked.
  if (real.size() > 10 && real.compare(real.size() - 10, 10, " (deleted)") == 0) return "";
  return real;
}

bool pathLiesUnder(const std::string& path, const std::string& folder) {
  std::filesystem::path rel = std::filesystem::path(path).lexically_relative(folder);
  return !rel.empty() && *rel.begin() != ".." && rel != ".";
}

std::optional<FileText> readFileChecked(const std::string& path, const FileReadRule& rule, FileReadFailure* failure) {
  auto fail = [&](FileReadFailure::Kind kind, int error = 0) -> std::optional<FileText> {
    if (failure) *failure = {kind, error};
    return std::nullopt;
  };
  int flags = O_RDONLY | O_CLOEXEC | (rule.regularOnly ? O_NONBLOCK : 0);
  int raw;
  do raw = ::open(path.c_str(), flags);
  while (raw < 0 && errno == EINTR);
  if (raw < 0) return fail(FileReadFailure::Kind::Open, errno);
  Descriptor fd(raw);
  struct stat st {};
  if (::fstat(fd.get(), &st) != 0) return fail(FileReadFailure::Kind::Read, errno);
  if (rule.regularOnly && !S_ISREG(st.st_mode)) return fail(FileReadFailure::Kind::NotRegular);
  if (S_ISDIR(st.st_mode)) return fail(FileReadFailure::Kind::Read, EISDIR);
  if (S_ISREG(st.st_mode) && static_cast<unsigned long long>(st.st_size) > rule.maxBytes)
    return fail(FileReadFailure::Kind::TooLarge);
  FileText text;
  if (S_ISREG(st.st_mode)) text.realPath = realPathOf(fd.get(), path, st);
  if (!rule.insideFolder.empty() || !rule.mustResolveTo.empty()) {
    if (text.realPath.empty()) return fail(FileReadFailure::Kind::Outside);
    if (!rule.insideFolder.empty() && !pathLiesUnder(text.realPath, rule.insideFolder))
      return fail(FileReadFailure::Kind::Outside);
    if (!rule.mustResolveTo.empty() && text.realPath != rule.mustResolveTo) return fail(FileReadFailure::Kind::Outside);
  }
  // Read until the end, not to st_size: the file may grow while it is read; one byte past
  // the limit is enough to know it is too large.
  char buf[65536];
  while (rule.readAtMost == 0 || text.bytes.size() < rule.readAtMost) {
    std::size_t want = sizeof buf;
    if (rule.readAtMost) want = std::min(want, rule.readAtMost - text.bytes.size());
    ssize_t n = ::read(fd.get(), buf, want);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return fail(FileReadFailure::Kind::Read, errno);
    if (n == 0) break;
    text.bytes.append(buf, static_cast<std::size_t>(n));
    if (text.bytes.size() > rule.maxBytes) return fail(FileReadFailure::Kind::TooLarge);
  }
  return text;
}

}  // namespace wg
