#include "core/graph_imports.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <system_error>
#include <unordered_map>

#include "core/color_parameters.h"
#include "core/file_read.h"
#include "core/graph_parse.h"
#include "core/load_limits.h"

namespace wg {
namespace {

namespace fs = std::filesystem;

bool holdsControlCharacter(std::string_view s) {
  return std::any_of(s.begin(), s.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; });
}


class ImportLoader {
 public:
  ImportLoader(const Graph& top, Diagnostics& diags) : diags_(diags) {
    std::error_code ec;
    fs::path file = fs::absolute(top.file, ec);
    topDir_ = fs::weakly_canonical(file.parent_path(), ec);
    fs::path real = fs::weakly_canonical(file, ec);
    chain_.push_back({real.string(), top.file});
  }

  bool load(Graph& g) {
    size_t errorsBefore = diags_.errorCount();
    loadImportsOf(g);
    return diags_.errorCount() == errorsBefore;
  }

 private:
  struct Link {
    std::string realPath;
    std::string shownPath;  // as diagnostics name the file
  };

  void loadImportsOf(Graph& g) {
    for (Import& im : g.imports) im.graph = loadOne(g, im);
  }

  std::shared_ptr<const Graph> loadOne(const Graph& from, Import& im) {
    const std::string what = "import '" + im.name + "' ('" + im.path + "')";
    if (holdsControlCharacter(im.path)) {
      diags_.error(DiagCode::ImportOutsideTree, im.pathWhere, what + " holds a control character");
      return nullptr;
    }
    fs::path written(im.path);
    if (written.is_absolute()) {
      diags_.error(DiagCode::ImportOutsideTree, im.pathWhere,
                   what + " is an absolute path; an import is relative to the file that writes it");
      return nullptr;
    }
    fs::path shown = (fs::path(from.file).parent_path() / written).lexically_normal();
    im.file = shown.string();
    std::error_code ec;
    if (!fs::is_regular_file(shown, ec)) {
      diags_.error(DiagCode::ImportMissing, im.pathWhere,
                   what + ": there is no file '" + shown.string() + "'" +
                       (fs::exists(shown, ec) ? " (it is not a regular file)" : ""));
      return nullptr;
    }
    fs::path real = fs::canonical(shown, ec);
    if (ec) {
      diags_.error(DiagCode::ImportMissing, im.pathWhere, what + ": cannot read '" + shown.string() + "': " + ec.message());
      return nullptr;
    }
    if (!pathLiesUnder(real.string(), topDir_.string())) {
      diags_.error(DiagCode::ImportOutsideTree, im.pathWhere,
                   what + " leaves the folder of the top-level graph ('" + topDir_.string() + "')");
      return nullptr;
    }
    auto onChain = std::find_if(chain_.begin(), chain_.end(), [&](const Link& l) { return l.realPath == real.string(); });
    if (onChain != chain_.end()) {
      std::string cycle;
      for (auto it = onChain; it != chain_.end(); ++it) cycle += "'" + it->shownPath + "' -> ";
      cycle += "'" + shown.string() + "'";
      diags_.error(DiagCode::ImportCycle, im.pathWhere, "graph files import each other in a cycle: " + cycle);
      return nullptr;
    }
    if (auto cached = loaded_.find(real.string()); cached != loaded_.end()) return cached->second;
    if (static_cast<int>(chain_.size()) > kMaxImportDepth) {
      std::string chain;
      for (const Link& l : chain_) chain += "'" + l.shownPath + "' -> ";
      diags_.error(DiagCode::ImportTooDeep, im.pathWhere,
                   what + " would make the chain of imports " + std::to_string(chain_.size()) +
                       " deep; the limit is " + std::to_string(kMaxImportDepth) + ": " + chain + "'" + shown.string() + "'");
      return nullptr;
    }

    size_t first = diags_.all().size();
    std::shared_ptr<Graph> sub;
    if (auto parsed = loadFile(shown.string(), real.string(), im)) sub = std::make_shared<Graph>(std::move(*parsed));
    if (sub) {
      chain_.push_back({real.string(), shown.string()});
      loadImportsOf(*sub);
      chain_.pop_back();
    }
    // What went wrong inside the file (or below it) says where it was imported from.
    diags_.addLocatedNoteFrom(first, {im.where, "imported as '" + im.name + "' from here"});
    if (sub && !sub->interface)
      diags_.error(DiagCode::NotAFunctionGraph, im.pathWhere,
                   what + ": '" + shown.string() +
                       "' declares no \"interface\"; only a function graph (one with an interface) can be used as a node type");
    std::shared_ptr<const Graph> result = sub;
    if (diags_.all().size() > first) result = nullptr;
    loaded_[real.string()] = result;
    return result;
  }

  // Each file is within kMaxFileBytes; all of them together within kMaxImportedBytes, so a
  // graph naming thousands of large files cannot make one compile hold gigabytes. The
  // checks above went by name; the file is read from one descriptor whose own real path is
  // checked again (core/file_read.h): a file swapped for a link since then is refused, never
  // read from outside the folder.
  std::optional<Graph> loadFile(const std::string& path, const std::string& realPath, const Import& im) {
    FileReadRule rule;
    rule.maxBytes = kMaxFileBytes;
    rule.insideFolder = topDir_.string();
    rule.mustResolveTo = realPath;
    FileReadFailure failure;
    auto text = readFileChecked(path, rule, &failure);
    if (!text) {
      const std::string what = "import '" + im.name + "' ('" + im.path + "')";
      if (failure.kind == FileReadFailure::Kind::TooLarge)
        diags_.error(DiagCode::LimitExceeded, im.pathWhere, "'" + path + "' is larger than the limit of 16 MiB");
      else if (failure.kind == FileReadFailure::Kind::Outside)
        diags_.error(DiagCode::ImportOutsideTree, im.pathWhere,
                     what + ": '" + path + "' changed while it was being read (it no longer is the file inside the folder of the top-level graph that was checked)");
      else
        diags_.error(DiagCode::ImportMissing, im.pathWhere, what + ": cannot read '" + path + "': " + failure.why());
      return std::nullopt;
    }
    bytesRead_ += text->bytes.size();
    if (bytesRead_ > kMaxImportedBytes) {
      diags_.error(DiagCode::LimitExceeded, im.pathWhere,
                   "import '" + im.name + "' would make the imported graph files " + std::to_string(bytesRead_) +
                       " bytes together; the limit is " + std::to_string(kMaxImportedBytes / (1024 * 1024)) + " MiB");
      return std::nullopt;
    }
    return parseGraph(std::make_shared<const std::string>(std::move(text->bytes)), path, diags_);
  }

  Diagnostics& diags_;
  fs::path topDir_;
  std::vector<Link> chain_;  // the top-level file, then each file being loaded below it
  std::map<std::string, std::shared_ptr<const Graph>> loaded_;  // by real path; null: failed
  std::size_t bytesRead_ = 0;  // of every imported file read
};

// Saturating: a tree of sixteen levels multiplies counts far past size_t's range.
size_t saturatingAdd(size_t a, size_t b, size_t cap) { return a >= cap || b >= cap - a ? cap : a + b; }
size_t saturatingMul(size_t a, size_t b, size_t cap) { return a != 0 && b >= (cap + a - 1) / a ? cap : a * b; }

constexpr size_t kNodeCap = kMaxNodes + 1;
constexpr size_t kByteCap = kMaxInlinedBytes + 1;

// What node `node` of a graph inlines to. An instance of `sub` is its nodes, each id behind
// the instance's ("inst/"), at least one node (an instance of an empty graph still stands).
InlinedSize nodeSize(const Node& node, const InlinedSize* sub) {
  if (!sub || sub->nodes == 0) return {1, saturatingAdd(node.id.size(), kInlinedNodeBytes, kByteCap)};
  size_t prefixes = saturatingMul(sub->nodes, node.id.size() + 1, kByteCap);
  return {sub->nodes, saturatingAdd(sub->bytes, prefixes, kByteCap)};
}

InlinedSize measureInlined(const Graph& g, std::unordered_map<const Graph*, InlinedSize>& memo) {
  if (auto it = memo.find(&g); it != memo.end()) return it->second;
  std::unordered_map<std::string_view, const Graph*> byName;
  for (const auto& im : g.imports)
    if (im.graph) byName.emplace(im.name, im.graph.get());
  InlinedSize total;
  for (const auto& node : g.nodes) {
    auto it = byName.find(node.type);
    std::optional<InlinedSize> sub;
    if (it != byName.end()) sub = measureInlined(*it->second, memo);
    InlinedSize n = nodeSize(node, sub ? &*sub : nullptr);
    total.nodes = saturatingAdd(total.nodes, n.nodes, kNodeCap);
    total.bytes = saturatingAdd(total.bytes, n.bytes, kByteCap);
    if (total.nodes == kNodeCap && total.bytes == kByteCap) break;
  }
  memo[&g] = total;
  return total;
}

}  // namespace

NodePorts interfacePorts(const Graph& g) {
  NodePorts ports;
  for (const auto& p : g.parameters) {
    Value def = Value::ofType(p.type, p.defaultValue.empty() ? 0 : p.defaultValue[0]);
    if (static_cast<int>(p.defaultValue.size()) == componentCount(p.type))
      for (size_t k = 0; k < p.defaultValue.size(); ++k) def[static_cast<int>(k)] = p.defaultValue[k];
    ports.inputs.push_back(PortSpec{p.name, PortKind::Fixed, p.type, def, std::nullopt, p.description});
    ports.inputs.back().color = isColorHint(p.hint);  // its literals and default are sRGB, as the parameter's
  }
  if (g.interface)
    for (const auto& o : g.interface->outputs)
      ports.outputs.push_back(PortSpec{o.name, PortKind::Fixed, o.type, std::nullopt, std::nullopt, o.description});
  return ports;
}

bool loadImports(Graph& graph, Diagnostics& diags) {
  if (graph.imports.empty()) return true;
  if (!ImportLoader(graph, diags).load(graph)) return false;
  // Predicted from the tree, before anything is inlined; reported at the instance that
  // takes the graph past a limit.
  std::unordered_map<const Graph*, InlinedSize> memo;
  std::unordered_map<std::string_view, const Graph*> byName;
  for (const auto& im : graph.imports) byName.emplace(im.name, im.graph.get());
  InlinedSize total;
  for (const auto& node : graph.nodes) {
    auto it = byName.find(node.type);
    std::optional<InlinedSize> sub;
    if (it != byName.end()) sub = measureInlined(*it->second, memo);
    InlinedSize n = nodeSize(node, sub ? &*sub : nullptr);
    total.nodes = saturatingAdd(total.nodes, n.nodes, kNodeCap);
    total.bytes = saturatingAdd(total.bytes, n.bytes, kByteCap);
    if (total.nodes > kMaxNodes) {
      diags.error(DiagCode::LimitExceeded, node.where,
                  "with instance '" + node.id + "' the graph has more than " + std::to_string(kMaxNodes) +
                      " nodes with every subgraph instance inlined; the limit is " + std::to_string(kMaxNodes),
                  node.id);
      return false;
    }
    if (total.bytes > kMaxInlinedBytes) {
      diags.error(DiagCode::LimitExceeded, node.where,
                  "with instance '" + node.id + "' the graph's inlined size (every node with every subgraph instance inlined, " +
                      "its full id and " + std::to_string(kInlinedNodeBytes) + " bytes each) passes the limit of " +
                      std::to_string(kMaxInlinedBytes / (1024 * 1024)) + " MiB: " + std::to_string(total.nodes) +
                      " nodes so far; shorten the ids or use fewer instances",
                  node.id);
      return false;
    }
  }
  return true;
}

size_t inlinedNodeCount(const Graph& graph) { return inlinedSize(graph).nodes; }

InlinedSize inlinedSize(const Graph& graph) {
  std::unordered_map<const Graph*, InlinedSize> memo;
  return measureInlined(graph, memo);
}

std::vector<std::string> graphFilesRead(const Graph& graph) {
  std::vector<std::string> files{graph.file};
  std::set<std::string> listed{graph.file};
  std::set<const Graph*> seen{&graph};
  std::vector<const Graph*> toVisit{&graph};
  for (size_t i = 0; i < toVisit.size(); ++i)
    for (const auto& im : toVisit[i]->imports) {
      const std::string& file = im.graph ? im.graph->file : im.file;
      if (!file.empty() && listed.insert(file).second) files.push_back(file);
      if (im.graph && seen.insert(im.graph.get()).second) toVisit.push_back(im.graph.get());
    }
  return files;
}

}  // namespace wg
