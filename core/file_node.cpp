#include "core/file_node.h"

#include <algorithm>
#include <filesystem>

#include "core/program.h"

namespace wg {

const NodeSpec* keepFileNode(Program& program, FileNode made) {
  namespace fs = std::filesystem;
  std::string relative =
      fs::path(made.path).lexically_normal().lexically_relative(fs::path(program.folder()).lexically_normal()).generic_string();
  if (std::find(program.functionFiles.begin(), program.functionFiles.end(), relative) == program.functionFiles.end())
    program.functionFiles.push_back(relative);
  program.fileNodeSpecs.push_back(std::move(made.spec));
  return program.fileNodeSpecs.back().get();
}

}  // namespace wg
