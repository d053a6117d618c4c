#include "editor/texture_choices.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "core/graph_node_type.h"
#include "core/texture_check.h"
#include "editor/function_node_ports.h"

namespace wg::editor {
namespace {

bool hasPngExtension(const std::filesystem::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".png";
}

}  // namespace

TextureChoices listGraphTextures(const std::string& graphDir) {
  namespace fs = std::filesystem;
  TextureChoices out;
  fs::path root = graphDir.empty() ? fs::path(".") : fs::path(graphDir);
  std::error_code ec;
  fs::recursive_directory_iterator it(root, fs::directory_options::skip_permission_denied, ec), end;
  // Candidates first (cheap), then the loader's check on each, in sorted order so the list
  // and where it is cut off do not depend on the directory's order.
  std::vector<std::string> candidates;
  for (; !ec && it != end; it.increment(ec)) {
    const fs::directory_entry& e = *it;
    std::string name = e.path().filename().string();
    std::error_code typeError;
    if (e.is_directory(typeError)) {
      if (!name.empty() && name[0] == '.') it.disable_recursion_pending();
      else if (it.depth() + 1 >= kTextureListDepth) it.disable_recursion_pending();
      continue;
    }
    if (!hasPngExtension(e.path())) continue;
    candidates.push_back(e.path().lexically_relative(root).generic_string());
    if (candidates.size() > 4 * kTextureListLimit) break;  // a huge tree: enough to show
  }
  std::sort(candidates.begin(), candidates.end());
  for (const std::string& c : candidates) {
    if (out.paths.size() == kTextureListLimit) {
      out.truncated = true;
      break;
    }
    if (checkTextureSource(c, graphDir).empty()) out.paths.push_back(c);
  }
  return out;
}

std::string chooseTexture(GraphEditor& editor, const Registry& registry, const std::string& graphDir,
                          const std::string& node, const std::string& option, const std::string& source) {
  const Node* n = editor.graph().findNode(node);
  if (!n) return "no node '" + node + "'";
  // A function node's sampler2D parameters are options of the type its file makes.
  std::shared_ptr<const NodeSpec> fromFile = fileNodeSpecOf(editor.graph(), registry, *n);
  const NodeSpec* spec = fromFile ? fromFile.get() : nodeTypeOf(editor.graph(), registry, n->type).spec;
  int index = spec ? spec->optionIndex(option) : -1;
  if (index < 0 || spec->options[static_cast<size_t>(index)].kind != OptionSpec::Kind::Texture)
    return "node '" + node + "' (" + n->type + ") has no texture option '" + option + "'";
  if (std::string why = checkTextureSource(source, graphDir); !why.empty()) return "texture '" + source + "' refused: " + why;
  Graph g = editor.graph();
  Node& m = *std::find_if(g.nodes.begin(), g.nodes.end(), [&](const Node& x) { return x.id == node; });
  auto it = std::find_if(m.options.begin(), m.options.end(), [&](const NodeOption& o) { return o.name == option; });
  if (it != m.options.end() && it->value == source) return "";
  if (it != m.options.end()) {
    it->value = source;
  } else {
    NodeOption o;
    o.name = option;
    o.value = source;
    o.where.file = o.keyWhere.file = g.file;
    m.options.push_back(std::move(o));
  }
  editor.replace(std::move(g), "set texture '" + option + "' of node '" + node + "' to '" + source + "'");
  return "";
}

}  // namespace wg::editor
