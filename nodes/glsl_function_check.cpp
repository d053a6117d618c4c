#include "nodes/glsl_function_check.h"

#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <cctype>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <sstream>

namespace wg {
namespace {

constexpr int kFunctionTargets = 3;  // glsl330, es300, vk450: every target a graph is emitted to
const char* const kFunctionTargetNames[kFunctionTargets] = {"glsl330", "es300", "vk450"};

void initialiseGlslangForFunctions() {
  // glslang counts its initialisations; the validator's own is another, never finalised.
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
}

struct GlslangError {
  int line = 0;  // in the function file; 0: none given
  std::string text;
};

// The first error of a glslang info log whose messages name the file `fileName`.
GlslangError firstError(const char* log, const std::string& fileName) {
  std::istringstream in{std::string(log ? log : "")};
  std::string raw;
  GlslangError fallback{0, "glslang refused the file"};
  bool haveFallback = false;
  while (std::getline(in, raw)) {
    if (raw.rfind("ERROR: ", 0) != 0) continue;
    std::string body = raw.substr(7);
    std::string prefix = fileName + ":";
    if (body.rfind(prefix, 0) == 0) {
      std::size_t colon = body.find(':', prefix.size());
      if (colon != std::string::npos) {
        try {
          int line = std::stoi(body.substr(prefix.size(), colon - prefix.size()));
          std::string text = body.substr(colon + 1);
          while (!text.empty() && text.front() == ' ') text.erase(0, 1);
          return {line, text};
        } catch (const std::exception&) {
        }
      }
    }
    if (!haveFallback && body.find("compilation error") == std::string::npos) {
      fallback.text = body;
      haveFallback = true;
    }
  }
  return fallback;
}

// The column of an error on `line` of `text`: the first place of the name glslang quotes
// ("'x' : undeclared identifier"), else the line's first character that is not blank.
int errorColumn(const std::string& text, int line, const std::string& message) {
  std::size_t start = 0;
  for (int l = 1; l < line && start != std::string::npos; ++l) {
    start = text.find('\n', start);
    if (start != std::string::npos) ++start;
  }
  if (start == std::string::npos || start > text.size()) return 1;
  std::size_t end = text.find('\n', start);
  std::string lineText = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
  std::size_t q = message.find('\'');
  std::size_t q2 = q == std::string::npos ? q : message.find('\'', q + 1);
  if (q2 != std::string::npos && q2 > q + 1) {
    std::size_t at = lineText.find(message.substr(q + 1, q2 - q - 1));
    if (at != std::string::npos) return static_cast<int>(at) + 1;
  }
  std::size_t first = lineText.find_first_not_of(" \t\r");
  return first == std::string::npos ? 1 : static_cast<int>(first) + 1;
}

// glslang places a definition at the ')' of its parameters and a parameter at the token
// after its name: the column of the last whole-word `name` on that line before `where`,
// else `where`'s own.
int nameColumn(const std::string& text, FunctionFilePlace where, const std::string& name) {
  std::size_t start = 0;
  for (int l = 1; l < where.line && start != std::string::npos; ++l) {
    start = text.find('\n', start);
    if (start != std::string::npos) ++start;
  }
  if (start == std::string::npos) return where.col;
  std::size_t end = text.find('\n', start);
  std::string line = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
  auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  int found = where.col;
  for (std::size_t k = line.find(name); k != std::string::npos && static_cast<int>(k) < where.col; k = line.find(name, k + 1)) {
    bool whole = (k == 0 || !word(line[k - 1])) && (k + name.size() >= line.size() || !word(line[k + name.size()]));
    if (whole) found = static_cast<int>(k) + 1;
  }
  return found;
}

// One parse of a function file for `target` as a vertex or fragment shader: the preamble,
// the file from its line 1 (so glslang's lines are the file's), an empty main.
struct FunctionParse {
  std::unique_ptr<glslang::TShader> shader;
  bool ok = false;
  GlslangError error;
};

FunctionParse parseFunctionFile(const std::string& text, const std::string& fileName, int target, EShLanguage stage) {
  initialiseGlslangForFunctions();
  FunctionParse p;
  p.shader = std::make_unique<glslang::TShader>(stage);
  const std::string preamble = functionCheckPreamble(target) + "#line 1\n";
  const std::string tail = "\nvoid main() {}\n";
  const char* strings[3] = {preamble.c_str(), text.c_str(), tail.c_str()};
  const int lengths[3] = {static_cast<int>(preamble.size()), static_cast<int>(text.size()), static_cast<int>(tail.size())};
  const char* names[3] = {fileName.c_str(), fileName.c_str(), fileName.c_str()};
  p.shader->setStringsWithLengthsAndNames(strings, lengths, names, 3);
  EShMessages messages = static_cast<EShMessages>(EShMsgKeepUncalled);
  if (target == 2) {
    p.shader->setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientVulkan, 100);
    p.shader->setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
    p.shader->setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
    messages = static_cast<EShMessages>(messages | EShMsgSpvRules | EShMsgVulkanRules);
  } else {
    p.shader->setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientNone, 0);
    p.shader->setEnvClient(glslang::EShClientNone, glslang::EShTargetClientVersion{});
    p.shader->setEnvTarget(glslang::EShTargetNone, glslang::EShTargetLanguageVersion{});
  }
  p.ok = p.shader->parse(GetDefaultResources(), 100, ENoProfile, false, false, messages);
  if (!p.ok) p.error = firstError(p.shader->getInfoLog(), fileName);
  return p;
}

// A type a port carries, or Invalid.
Type portTypeOf(const glslang::TType& t) {
  if (t.isArray() || t.isStruct()) return Type::Invalid;
  if (t.getBasicType() == glslang::EbtSampler) {
    const glslang::TSampler& s = t.getSampler();
    bool plain2D = s.dim == glslang::Esd2D && !s.arrayed && !s.shadow && !s.ms && s.isCombined() &&
                   s.type == glslang::EbtFloat;
    return plain2D ? Type::Sampler2D : Type::Invalid;
  }
  if (t.getBasicType() != glslang::EbtFloat) return Type::Invalid;
  if (t.isMatrix()) {
    if (t.getMatrixCols() == 3 && t.getMatrixRows() == 3) return Type::Mat3;
    if (t.getMatrixCols() == 4 && t.getMatrixRows() == 4) return Type::Mat4;
    return Type::Invalid;
  }
  return floatVector(t.getVectorSize());
}

std::string describeType(const glslang::TType& t) {
  std::string s(t.getBasicTypeString().c_str());
  if (t.isMatrix()) s = "mat" + std::to_string(t.getMatrixCols()) + (t.getMatrixCols() != t.getMatrixRows() ? "x" + std::to_string(t.getMatrixRows()) : "");
  else if (t.isVector()) s = std::string(t.getBasicType() == glslang::EbtFloat ? "vec" : "a vector of ") + std::to_string(t.getVectorSize()) + (t.getBasicType() == glslang::EbtFloat ? "" : " " + s);
  if (t.isArray()) s += " array";
  return s;
}

std::string baseName(const glslang::TString& mangled) {
  std::string s(mangled.c_str());
  return s.substr(0, s.find('('));
}

struct FunctionDefinition {
  std::string mangled, name;
  glslang::TIntermAggregate* node = nullptr;
  std::set<std::string> calls;  // mangled names of user functions it calls
};

class CallCollector : public glslang::TIntermTraverser {
 public:
  std::set<std::string> calls;
  bool visitAggregate(glslang::TVisit, glslang::TIntermAggregate* a) override {
    if (a->getOp() == glslang::EOpFunctionCall && a->isUserDefined()) calls.insert(a->getName().c_str());
    return true;
  }
};

std::vector<FunctionDefinition> definitionsOf(const glslang::TIntermediate& im) {
  std::vector<FunctionDefinition> out;
  TIntermNode* root = im.getTreeRoot();
  glslang::TIntermAggregate* seq = root ? root->getAsAggregate() : nullptr;
  if (!seq) return out;
  for (TIntermNode* child : seq->getSequence()) {
    glslang::TIntermAggregate* fn = child ? child->getAsAggregate() : nullptr;
    if (!fn || fn->getOp() != glslang::EOpFunction) continue;
    FunctionDefinition d{fn->getName().c_str(), baseName(fn->getName()), fn, {}};
    if (d.name == "main") continue;
    CallCollector calls;
    fn->traverse(&calls);
    d.calls = std::move(calls.calls);
    out.push_back(std::move(d));
  }
  return out;
}

FunctionFilePlace placeOf(const glslang::TSourceLoc& loc) { return {loc.line > 0 ? loc.line : 1, loc.column > 0 ? loc.column : 1}; }

// A chain of calls that comes back to where it started ("a -> b -> a"), or "".
std::string recursionFrom(const std::vector<FunctionDefinition>& defs, std::size_t start) {
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < defs.size(); ++i) index[defs[i].mangled] = i;
  std::vector<std::size_t> path{start};
  std::vector<char> onPath(defs.size(), 0), done(defs.size(), 0);
  std::string found;
  std::function<bool(std::size_t)> visit = [&](std::size_t i) {
    onPath[i] = 1;
    for (const std::string& callee : defs[i].calls) {
      auto it = index.find(callee);
      if (it == index.end()) continue;
      path.push_back(it->second);
      if (onPath[it->second]) {
        for (std::size_t k = 0; k < path.size(); ++k) {
          if (!found.empty() || path[k] == it->second)
            found += (found.empty() ? "" : " -> ") + defs[path[k]].name;
        }
        return true;
      }
      if (!done[it->second] && visit(it->second)) return true;
      path.pop_back();
    }
    onPath[i] = 0;
    done[i] = 1;
    return false;
  };
  visit(start);
  return found;
}

std::optional<FunctionCheckFault> signatureOf(const FunctionDefinition& def, FunctionSignature& sig) {
  auto fault = [&](FunctionCheckFault::Kind kind, const glslang::TSourceLoc& loc, std::string message,
                   std::string name = {}) {
    return FunctionCheckFault{kind, placeOf(loc), std::move(message), name.empty() ? def.name : std::move(name)};
  };
  const std::string carried = "a port carries float, vec2, vec3, vec4, mat3 or mat4, and a texture input is an 'in sampler2D'";
  sig.name = def.name;
  sig.where = placeOf(def.node->getLoc());
  const glslang::TType& ret = def.node->getType();
  if (ret.getBasicType() != glslang::EbtVoid) {
    sig.returns = portTypeOf(ret);
    if (sig.returns == Type::Invalid || sig.returns == Type::Sampler2D)
      return fault(FunctionCheckFault::Kind::ParameterType, def.node->getLoc(),
                   "function '" + def.name + "' returns " + describeType(ret) + ", which a port cannot carry: " + carried);
  }
  const glslang::TIntermSequence& parts = def.node->getSequence();
  glslang::TIntermAggregate* params = parts.empty() || !parts[0] ? nullptr : parts[0]->getAsAggregate();
  if (params && params->getOp() == glslang::EOpParameters) {
    for (TIntermNode* p : params->getSequence()) {
      glslang::TIntermSymbol* sym = p ? p->getAsSymbolNode() : nullptr;
      if (!sym) continue;
      const glslang::TType& t = sym->getType();
      std::string name(sym->getName().c_str());
      const glslang::TStorageQualifier q = t.getQualifier().storage;
      if (name.empty())
        return fault(FunctionCheckFault::Kind::ParameterType, sym->getLoc(),
                     "every parameter of function '" + def.name + "' needs a name: it names the node's port");
      if (q == glslang::EvqInOut)
        return fault(FunctionCheckFault::Kind::ParameterType, sym->getLoc(),
                     "parameter '" + name + "' is 'inout'; a port is an input or an output: write an 'in' and an 'out' parameter",
                     name);
      FunctionParameter fp{name, portTypeOf(t), q == glslang::EvqOut};
      if (fp.type == Type::Invalid || (fp.type == Type::Sampler2D && fp.out))
        return fault(FunctionCheckFault::Kind::ParameterType, sym->getLoc(),
                     "parameter '" + name + "' has the type " + describeType(t) + (fp.out ? " as an output" : "") +
                         ", which a port cannot carry: " + carried,
                     name);
      if (name == "out" || name == "file" || name == "function" || name == "reference" || name == "input_roundings")
        return fault(FunctionCheckFault::Kind::ParameterType, sym->getLoc(),
                     "parameter '" + name + "' would share its name with the node's " +
                         (name == "out" ? "return value" : "option") + "; rename it",
                     name);
      if (name.size() > 64)
        return fault(FunctionCheckFault::Kind::ParameterType, sym->getLoc(),
                     "parameter name '" + name.substr(0, 16) + "...' is longer than 64 characters, the longest port name");
      sig.parameters.push_back(std::move(fp));
    }
  }
  bool anyOutput = sig.returns != Type::Invalid;
  for (const auto& p : sig.parameters) anyOutput |= p.out;
  if (!anyOutput)
    return fault(FunctionCheckFault::Kind::ParameterType, def.node->getLoc(),
                 "function '" + def.name + "' returns nothing and has no 'out' parameter: the node would have no output");
  return std::nullopt;
}

FunctionCheckFault syntaxFault(const FunctionParse& p, const std::string& text, int target, FunctionCheckFault::Kind kind,
                               const std::string& what) {
  FunctionCheckFault f;
  f.kind = kind;
  f.where.line = p.error.line > 0 ? p.error.line : 1;
  f.where.col = p.error.line > 0 ? errorColumn(text, p.error.line, p.error.text) : 1;
  f.message = what + "glslang (" + kFunctionTargetNames[target] + ") refuses it: " + p.error.text;
  // glslang reads the file and then an empty main() on the line after its last: an error
  // there is the file ending inside a declaration, placed where the file ends. (glslang
  // counts lines at LF alone, as this file's line numbers do: a lone CR ends none.)
  const int lastLine = 1 + static_cast<int>(std::count(text.begin(), text.end(), '\n'));
  if (f.where.line > lastLine) {
    const std::size_t lastStart = text.rfind('\n');
    f.where.line = lastLine;
    f.where.col = static_cast<int>(text.size() - (lastStart == std::string::npos ? 0 : lastStart + 1)) + 1;
    f.message = what + "the file ends inside a declaration; glslang (" + kFunctionTargetNames[target] +
                ") refuses it: " + p.error.text;
  }
  return f;
}

}  // namespace

std::string functionCheckPreamble(int target) {
  switch (target) {
    case 1:
      // As the generated es300 shaders declare them (codegen/emit_glsl.cpp).
      return "#version 300 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n"
             "precision highp samplerCube;\n";
    case 2: return "#version 450\n";
    default: return "#version 330 core\n";
  }
}

namespace {

// The function `function` among the file's definitions, its signature, and the faults of
// the call graph. Run on the glsl330 parse while it is the thread's latest: glslang's
// traversal allocates from the pool of the last shader parsed.
std::optional<FunctionCheckFault> analyseDefinitions(const glslang::TIntermediate& im, const std::string& function,
                                                     FunctionSignature& signature) {
  std::vector<FunctionDefinition> defs = definitionsOf(im);
  std::vector<const FunctionDefinition*> named;
  std::string available;
  for (const auto& d : defs) {
    if (d.name == function) named.push_back(&d);
    available += (available.empty() ? "" : ", ") + d.name;
  }
  if (named.empty())
    return FunctionCheckFault{FunctionCheckFault::Kind::NoSuchFunction, {1, 1},
                              "the file defines no function '" + function + "'" +
                                  (available.empty() ? "; it defines none" : "; it defines: " + available)};
  if (named.size() > 1)
    return FunctionCheckFault{FunctionCheckFault::Kind::Overloaded, placeOf(named[1]->node->getLoc()),
                              "function '" + function + "' is overloaded (" + std::to_string(named.size()) +
                                  " definitions): a node calls exactly one; give each its own name",
                              function};
  for (std::size_t i = 0; i < defs.size(); ++i) {
    std::string chain = recursionFrom(defs, i);
    if (!chain.empty())
      return FunctionCheckFault{FunctionCheckFault::Kind::Recursion, placeOf(defs[i].node->getLoc()),
                                "recursion (" + chain + "): GLSL forbids a function that calls itself", defs[i].name};
  }
  std::set<std::string> defined;
  for (const auto& d : defs) defined.insert(d.mangled);
  for (const auto& d : defs)
    for (const auto& c : d.calls)
      if (!defined.count(c))
        return FunctionCheckFault{FunctionCheckFault::Kind::NoSuchFunction, placeOf(d.node->getLoc()),
                                  "function '" + d.name + "' calls '" + c.substr(0, c.find('(')) +
                                      "', which the file declares but does not define",
                                  d.name};
  return signatureOf(*named.front(), signature);
}

}  // namespace

FunctionCheck checkFunctionFile(const std::string& text, const std::string& fileName, const std::string& function,
                                const std::string& renamed) {
  FunctionCheck r;
  // The file as written, for every target: its errors point at its own names and places.
  std::optional<FunctionCheckFault> analysed;
  for (int target = 0; target < kFunctionTargets; ++target) {
    FunctionParse p = parseFunctionFile(text, fileName, target, EShLangFragment);
    if (!p.ok) {
      r.fault = syntaxFault(p, text, target, FunctionCheckFault::Kind::Syntax, "");
      return r;
    }
    if (target == 0) analysed = analyseDefinitions(*p.shader->getIntermediate(), function, r.signature);
  }
  if (analysed) {
    r.fault = analysed;
    if (!analysed->name.empty()) r.fault->where.col = nameColumn(text, analysed->where, analysed->name);
    return r;
  }
  // A vertex shader may not take derivatives: such a function runs in the fragment stage only.
  for (int target = 0; target < kFunctionTargets && !r.signature.fragmentOnly; ++target)
    r.signature.fragmentOnly = !parseFunctionFile(text, fileName, target, EShLangVertex).ok;
  // What reaches a shader is the renamed text: glslang must accept it too, for every target.
  for (int target = 0; target < kFunctionTargets; ++target) {
    for (EShLanguage stage : {EShLangFragment, EShLangVertex}) {
      if (stage == EShLangVertex && r.signature.fragmentOnly) continue;
      FunctionParse p = parseFunctionFile(renamed, fileName, target, stage);
      if (!p.ok) {
        r.fault = syntaxFault(p, renamed, target, FunctionCheckFault::Kind::NameClash,
                              "renamed into the node's namespace, the file no longer compiles (a name would clash after "
                              "renaming); ");
        return r;
      }
    }
  }
  return r;
}

}  // namespace wg
