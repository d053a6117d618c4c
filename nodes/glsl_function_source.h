#pragma once
// The text of a user's GLSL function file (a `glsl_function` node's `file`), read as
// tokens before glslang sees it: what the file may not declare (uniforms, inputs and
// outputs, `main`, preprocessor lines, mutable globals, structs, precision statements,
// names reserved for the generated shader), the names it declares at the top level
// (functions and constants), and the same text with those names moved into one node's
// namespace. glslang parses and checks the rest (nodes/glsl_function_check.h).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace wg {

// A function file is small: anything larger is refused before it is read whole.
inline constexpr std::size_t kMaxFunctionFileBytes = 1u << 20;

// A place in the function file: 1-based line and byte column.
struct FunctionFilePlace {
  int line = 1;
  int col = 1;
};

struct FunctionFileFault {
  FunctionFilePlace where;
  std::string message;
};

struct FunctionFileNames {
  std::vector<std::string> functions;  // top-level function names, each once, in file order
  std::vector<std::string> constants;  // top-level constants, in file order
};

// The first fault of the file's text (a forbidden declaration or a reserved name), or the
// names it declares.
struct FunctionFileScan {
  std::optional<FunctionFileFault> fault;
  FunctionFileNames names;
};
FunctionFileScan scanFunctionFile(std::string_view text);

// The prefix a node's namespace gives every top-level name of its file: "wgfn<k>_".
std::string functionNamespace(int k);

// `text` with every top-level name (as a whole identifier, not after a '.') prefixed by
// `prefix`; everything else, comments and line breaks included, as written, so a line of
// the renamed text is the same line of the file.
std::string renameFunctionFile(std::string_view text, const FunctionFileNames& names, const std::string& prefix);

// Where byte `offset` of `text` lies.
FunctionFilePlace placeInText(std::string_view text, std::size_t offset);

}  // namespace wg
