#pragma once
// A user's GLSL function file checked by glslang before any byte of it reaches a shader:
// parsed for every target a graph is emitted to (glsl330, es300 with its precision, vk450),
// the one function the node names found among the file's definitions (not missing, not
// overloaded), no function calling itself through any chain, every parameter and the
// return value of a type a port carries, and the file renamed into the node's namespace
// accepted again for every target. The signature becomes the node's ports.
#include <optional>
#include <string>
#include <vector>

#include "core/types.h"
#include "nodes/glsl_function_source.h"

namespace wg {

struct FunctionParameter {
  std::string name;
  Type type = Type::Float;
  bool out = false;  // an `out` parameter: one more output of the node
};

struct FunctionSignature {
  std::string name;
  Type returns = Type::Invalid;  // Invalid: void
  std::vector<FunctionParameter> parameters;
  FunctionFilePlace where;          // the definition's name
  bool fragmentOnly = false;        // glslang refuses it in a vertex shader (derivatives)
};

struct FunctionCheckFault {
  enum class Kind { Syntax, NoSuchFunction, Overloaded, Recursion, ParameterType, NameClash } kind = Kind::Syntax;
  FunctionFilePlace where;
  std::string message;
  std::string name;  // the function or parameter it is about: `where` is moved onto it
};

struct FunctionCheck {
  std::optional<FunctionCheckFault> fault;
  FunctionSignature signature;
};

// `text` is the file as written (named `fileName` in glslang's messages), `renamed` the same
// text renamed by `prefix` (renameFunctionFile); `function` the name the node gives.
FunctionCheck checkFunctionFile(const std::string& text, const std::string& fileName, const std::string& function,
                                const std::string& renamed);

// The text each target's shader starts with before a function file (the version line and,
// for es300, the default precisions of the generated shader), for the checks and the tests.
std::string functionCheckPreamble(int target);  // 0 glsl330, 1 es300, 2 vk450

}  // namespace wg
