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

// The op that samples `source`: its file decides the folder a relative path is read from.
const Op* samplingOp(const Program& program, const std::string& source) {
  for (const auto& op : program.ops) {
    if (!op.options.is_object()) continue;
    for (const auto& [key, value] : op.options.items())
      if (value.is_string() && value.get<std::string>() == source) return &op;
  }
  return nullptr;
}

}  // namespace

std::string textureFileName(const std::string& graphName, const std::string& sampler) {
  return graphName + "." + sampler + ".png";
}

std::vector<OutputFile> textureFiles(const CompileResult& result, const std::string& graphName, Diagnostics& diags) {
  std::vector<OutputFile> files;
  const auto& textures = result.manifest.value("textures", nlohmann::json::array());
  for (const auto& t : textures) {
    if (!t.contains("source")) continue;  // a scene resource: rendered by a pass, not a file
    std::string source = t.value("source", "");
    std::string sampler = t.value("name", "");
    const Op* op = samplingOp(result.program, source);
    SourceRef where = op ? op->where : SourceRef{};
    std::string node = op ? op->nodeId : std::string();
    std::filesystem::path file(where.file.str());
    std::string dir = file.has_parent_path() ? file.parent_path().string() : ".";
    std::string why;
    auto img = loadTexture(source, dir, &why);
    std::string png = img ? encodePng(*img) : std::string();
    if (!img || png.empty()) {
      diags.error(DiagCode::FileRead, where,
                  "texture '" + source + "' cannot be exported as " + textureFileName(graphName, sampler) + ": " +
                      (why.empty() ? "PNG encoding failed" : why),
                  node);
      continue;
    }
    files.push_back({textureFileName(graphName, sampler), std::move(png)});
  }
  return files;
}

}  // namespace wg
