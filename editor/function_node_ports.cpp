#include "editor/function_node_ports.h"

#include <sys/stat.h>

#include <filesystem>
#include <map>
#include <set>

#include "core/file_node.h"
#include "core/graph_node_type.h"

namespace wg::editor {
namespace {

namespace fs = std::filesystem;

std::string folderOf(const std::string& file) { return fs::path(file).parent_path().string(); }

// The file named by the node's "file" option, from the working folder ("" when none).
std::string namedFile(const Node& node, const std::string& graphDir) {
  for (const NodeOption& o : node.options)
    if (o.name == "file" && o.value.is_string() && !o.value.get_ref<const std::string&>().empty())
      return (fs::path(graphDir.empty() ? "." : graphDir) / o.value.get<std::string>()).lexically_normal().string();
  return "";
}

std::string fileStamp(const std::string& path) {
  struct stat st {};
  if (path.empty() || ::stat(path.c_str(), &st) != 0) return "missing";
  return std::to_string(st.st_mtim.tv_sec) + "." + std::to_string(st.st_mtim.tv_nsec) + "/" + std::to_string(st.st_size) + "/" +
         std::to_string(st.st_ino);
}

// Made specs by (folder, options, file stamp); a failure is remembered too (null), until the
// file or the options change. Bounded: a long session edits many versions of a file.
std::map<std::string, std::shared_ptr<const NodeSpec>>& madeFileSpecs() {
  static std::map<std::string, std::shared_ptr<const NodeSpec>> made;
  return made;
}

void collectFunctionFiles(const Graph& graph, const Registry& registry, std::set<std::string>& seen, std::vector<std::string>& out,
                          int depth) {
  const std::string dir = folderOf(graph.file);
  for (const Node& n : graph.nodes)
    if (registry.fileNodeType(n.type))
      if (std::string f = namedFile(n, dir); !f.empty() && seen.insert(f).second) out.push_back(f);
  if (depth > 16) return;  // imports are acyclic (the loader refuses cycles); a bound all the same
  for (const Import& im : graph.imports)
    if (im.graph) collectFunctionFiles(*im.graph, registry, seen, out, depth + 1);
}

}  // namespace

std::shared_ptr<const NodeSpec> fileNodeSpecOf(const Graph& graph, const Registry& registry, const Node& node) {
  const FileNodeMaker* make = registry.fileNodeType(node.type);
  if (!make) return nullptr;
  const std::string dir = folderOf(graph.file);
  std::string key = dir + "\n" + writtenOptions(node).dump() + "\n" + fileStamp(namedFile(node, dir));
  auto& made = madeFileSpecs();
  if (auto it = made.find(key); it != made.end()) return it->second;
  if (made.size() >= 256) made.clear();
  Diagnostics reportedByCompiling;
  std::optional<FileNode> file = (*make)(FileNodeRequest{node, dir, 0}, reportedByCompiling);
  return made[key] = file ? file->spec : nullptr;
}

std::optional<NodePorts> editorPortsOf(const Graph& graph, const Registry& registry, const Node& node) {
  if (std::shared_ptr<const NodeSpec> spec = fileNodeSpecOf(graph, registry, node)) return NodePorts{spec->inputs, spec->outputs};
  return portsOfGraphNode(graph, registry, node);
}

std::vector<std::string> functionFilesOf(const Graph& graph, const Registry& registry) {
  std::set<std::string> seen;
  std::vector<std::string> out;
  collectFunctionFiles(graph, registry, seen, out, 0);
  return out;
}

}  // namespace wg::editor
