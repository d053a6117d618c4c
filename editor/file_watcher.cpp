#include "editor/file_watcher.h"

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <set>

#include "core/graph_imports.h"
#include "editor/function_node_ports.h"
#include "nodes/registry.h"

namespace wg::editor {

// graphFilesRead lists an import that did not load by the path it names (Import::file), so
// that repairing or creating that file is noticed; function nodes' .glsl files follow.
std::vector<std::string> filesToWatch(const Graph& graph) {
  std::vector<std::string> files = graphFilesRead(graph);
  for (std::string& f : functionFilesOf(graph, defaultRegistry())) files.push_back(std::move(f));
  return files;
}

FileWatcher::Stamp FileWatcher::stamp(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return {};
  return {static_cast<long long>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec, static_cast<long long>(st.st_size),
          static_cast<long long>(st.st_ino)};
}

void FileWatcher::watch(const std::vector<std::string>& paths) {
  std::vector<Stamp> stamps;
  for (const auto& p : paths) {
    auto known = std::find(paths_.begin(), paths_.end(), p);
    stamps.push_back(known != paths_.end() ? last_[static_cast<size_t>(known - paths_.begin())] : stamp(p));
  }
  paths_ = paths;
  last_ = std::move(stamps);
}

bool FileWatcher::changed() {
  bool any = false;
  for (size_t i = 0; i < paths_.size(); ++i) {
    Stamp now = stamp(paths_[i]);
    if (now == last_[i]) continue;
    last_[i] = now;
    any |= now.size >= 0;  // a file that disappeared (mid-rename) is not a change yet
  }
  return any;
}

void FileWatcher::acknowledge(const std::string& path) {
  for (size_t i = 0; i < paths_.size(); ++i)
    if (paths_[i] == path) last_[i] = stamp(path);
}

}  // namespace wg::editor
