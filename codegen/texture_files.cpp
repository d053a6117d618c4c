#include "codegen/texture_files.h"

#include <algorithm>
#include <filesystem>

#include <stb/stb_image_write.h>

#include "nodes/texture_source.h"

namespace wg {
namespace {

void appendBytes(void* context, void* data, int size) {
  auto* out = static_cast<std::string*>(context);
  out->append(static_cast<const char*>(data), static_cast<size_t>(size));
}

// PNG bytes of a texture; GL's row 0 (v = 0) becomes the picture's last row.
std::string encodePng(const TextureImage& img) {
  const size_t row = static_cast<size_t>(img.width) * 4;
  std::vector<std::uint8_t> flipped(img.rgba.size());
  for (int y = 0; y < img.height; ++y)
    std::copy_n(img.rgba.begin() + static_cast<long>(static_cast<size_t>(y) * row), row,
                flipped.begin() + static_cast<long>(static_cast<size_t>(img.height - 1 - y) * row));
  std::string png;
  if (!stbi_write_png_to_func(appendBytes, &png, img.width, img.height, 4, flipped.data(), static_cast<int>(row)))
    png.clear();
  return png;
}

// The op that samples `source` (its file decides the folder a relative path is read from),
// and the name of the option that names it.
const Op* samplingOp(const Program& program, const std::string& source, std::string* option) {
  for (const auto& op : program.ops) {
    if (!op.options().is_object()) continue;
    for (const auto& [key, value] : op.options().items())
      if (value.is_string() && value.get<std::string>() == source) {
        *option = key;
        return &op;
      }
  }
  return nullptr;
}

// Where the graph file names the texture: the option's value, else the node.
SourceRef optionPosition(const Graph* graph, const Op& op, const std::string& option) {
  if (graph)
    if (const Node* n = graph->findNode(op.nodeId))
      for (const auto& o : n->options)
        if (o.name == option) return o.where;
  return op.where;
}

}  // namespace

void reportUnusableTexture(const Program& program, const Graph* graph, const std::string& source,
                           const std::string& why, Diagnostics& diags) {
  // The graph names a texture that cannot be decoded: a fault of the graph's input, as a
  // path outside its folder is, not of the tool's I/O.
  std::string option;
  const Op* op = samplingOp(program, source, &option);
  if (!op) {
    diags.error(DiagCode::InvalidOption, SourceRef{graph ? graph->file : std::string(), 1, 1},
                "texture '" + source + "' is not usable: " + why);
    return;
  }
  withInstanceNotes(diags.error(DiagCode::InvalidOption, optionPosition(graph, *op, option),
                                "option '" + option + "' is not usable: " + why, op->nodeId, "option '" + option + "'"),
                    *op);
}

std::string textureFileName(const std::string& graphName, const std::string& sampler) {
  return graphName + "." + sampler + ".png";
}

std::vector<OutputFile> textureFiles(const CompileResult& result, Diagnostics& diags, const Graph* graph) {
  std::vector<OutputFile> files;
  for (const auto& t : result.manifest.textures) {
    if (t.source.empty()) continue;  // a scene resource: rendered by a pass, not a file
    const std::string& source = t.source;
    std::string option;
    const Op* op = samplingOp(result.program, source, &option);
    SourceRef where = op ? optionPosition(graph, *op, option) : SourceRef{};
    std::string node = op ? op->nodeId : std::string();
    // Relative to the top graph's folder, also for a subgraph's texture (its path was
    // rewritten so when the subgraph was inlined), not to the op's own file.
    std::string dir = result.program.folder();
    std::string why;
    auto img = loadTexture(source, dir, &why);
    if (!img) {
      reportUnusableTexture(result.program, graph, source, why, diags);
      continue;
    }
    std::string png = encodePng(*img);
    if (png.empty()) {
      diags.error(DiagCode::FileWrite, where,
                  "texture '" + source + "' cannot be exported as " + t.file +
                      ": PNG encoding failed",
                  node);
      continue;
    }
    files.push_back({t.file, std::move(png)});  // the name the manifest records
  }
  return files;
}

}  // namespace wg
