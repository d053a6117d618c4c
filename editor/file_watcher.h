#pragma once
// Notices when files change on disk (another editor saved them) by polling their
// modification time, size and inode: cheap, and it works for editors that write in place
// and for those that write a temporary file and rename it over the original. The editor
// watches the graph it shows, every file that graph imports and its function files.
#include <string>
#include <vector>

#include "core/graph.h"

namespace wg::editor {

// The files to watch for `graph`: its own and every imported one (graphFilesRead), where an
// import that did not load would be, so that fixing or creating it is noticed, and the
// .glsl files its function nodes name (editor/function_node_ports.h).
std::vector<std::string> filesToWatch(const Graph& graph);

class FileWatcher {
 public:
  explicit FileWatcher(std::string path) { watch({std::move(path)}); }
  // Watches these files from now on; one already watched keeps what was seen of it, so a
  // change made before the call is still reported.
  void watch(const std::vector<std::string>& paths);
  // True once per change of any watched file since the last call (or acknowledge()).
  bool changed();
  // Takes `path` as it is now as seen (after our own save).
  void acknowledge(const std::string& path);
  const std::vector<std::string>& paths() const { return paths_; }

 private:
  struct Stamp {
    long long mtimeNs = -1, size = -1, inode = -1;
    bool operator==(const Stamp&) const = default;
  };
  static Stamp stamp(const std::string& path);
  std::vector<std::string> paths_;
  std::vector<Stamp> last_;  // per path
};

}  // namespace wg::editor
