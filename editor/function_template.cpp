#include "editor/function_template.h"

#include <filesystem>

#include "codegen/output_files.h"
#include "nodes/glsl_function_node.h"

namespace wg::editor {

std::string functionTemplateText(const std::string& name) {
  return "// " + name +
         ".glsl: the function a glsl_function node calls (docs/graph-format.md, \"GLSL function\n"
         "// nodes\"). Its parameters are the node's inputs, its return value the output \"out\"; an\n"
         "// `out` parameter adds an output, a sampler2D parameter a texture option. Helper\n"
         "// functions and const globals may sit beside it. The editor follows each save.\n"
         "vec3 " + name + "(vec2 uv, float scale) {\n"
         "  vec2 cell = fract(uv * scale);\n"
         "  return vec3(cell, 0.5);\n"
         "}\n";
}

std::string addFunctionNodeFromTemplate(GraphEditor& editor, const Registry& registry, const std::string& graphDir,
                                        const std::string& name, std::array<double, 2> position, std::string* usedId) {
  namespace fs = std::filesystem;
  if (!isIdentifier(name)) return "'" + name + "' is not an identifier ([A-Za-z_][A-Za-z0-9_]*, at most 64)";
  for (const char* reserved : {"wg_", "WG_", "wgfn"})
    if (name.rfind(reserved, 0) == 0) return "names beginning with " + std::string(reserved) + " are reserved";
  const std::string file = name + ".glsl";
  const fs::path path = fs::path(graphDir.empty() ? "." : graphDir) / file;
  std::error_code ec;
  if (fs::exists(fs::symlink_status(path, ec))) return path.string() + " exists already (add a glsl_function node naming it instead)";
  // The node first, on a scratch copy: a refusal there writes no file.
  GraphEditor scratch(editor.graph(), &registry);
  std::string id;
  if (std::string why = scratch.addNode(kGlslFunctionType, "", position, &id); !why.empty()) return why;
  if (std::string why = scratch.setOption(id, "file", file); !why.empty()) return why;
  if (std::string why = scratch.setOption(id, "function", name); !why.empty()) return why;
  Diagnostics d;
  if (!writeFileAtomically(path.string(), functionTemplateText(name), d))
    return d.all().empty() ? "cannot write " + path.string() : d.all().front().message;
  editor.replace(scratch.graph(), "new function node '" + id + "' calling " + file);
  if (usedId) *usedId = id;
  return "";
}

}  // namespace wg::editor
