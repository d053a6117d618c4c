#include "editor/file_watcher.h"

#include <sys/stat.h>

namespace wg::editor {

FileWatcher::FileWatcher(std::string path) : path_(std::move(path)) { last_ = stamp(); }

FileWatcher::Stamp FileWatcher::stamp() const {
  struct stat st {};
  if (::stat(path_.c_str(), &st) != 0) return {};
  return {static_cast<long long>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec, static_cast<long long>(st.st_size),
          static_cast<long long>(st.st_ino)};
}

bool FileWatcher::changed() {
  Stamp now = stamp();
  if (now == last_) return false;
  last_ = now;
  return now.size >= 0;  // a file that disappeared (mid-rename) is not a change yet
}

void FileWatcher::acknowledge() { last_ = stamp(); }

}  // namespace wg::editor
