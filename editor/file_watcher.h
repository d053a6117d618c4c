#pragma once
// Notices when a file changes on disk (another editor saved it) by polling its
// modification time, size and inode: cheap, and it works for editors that write in place
// and for those that write a temporary file and rename it over the original.
#include <string>

namespace wg::editor {

class FileWatcher {
 public:
  explicit FileWatcher(std::string path);
  // True once per change since the last call (or since acknowledge()).
  bool changed();
  // Takes the file as it is now as seen (after our own save).
  void acknowledge();
  const std::string& path() const { return path_; }

 private:
  struct Stamp {
    long long mtimeNs = -1, size = -1, inode = -1;
    bool operator==(const Stamp&) const = default;
  };
  Stamp stamp() const;
  std::string path_;
  Stamp last_;
};

}  // namespace wg::editor
