#include "core/emit_context.h"
#include "nodes/glsl_function_node.h"

#include <algorithm>
#include <filesystem>

#include "core/file_read.h"
#include "core/texture_check.h"
#include "nodes/glsl_function_check.h"
#include "nodes/glsl_function_reference.h"
#include "nodes/glsl_function_source.h"

namespace wg {
namespace {

namespace fs = std::filesystem;

const NodeOption* writtenOption(const Node& n, std::string_view name) {
  for (const auto& o : n.options)
    if (o.name == name) return &o;
  return nullptr;
}

// The path rules of textures and imports: relative, no control character, inside the
// folder of the graph that names it after every symbolic link; a regular file of at most
// kMaxFunctionFileBytes, read once from the descriptor that was checked (core/file_read.h).
// "" and the text, or why not.
std::string readFunctionFile(const std::string& source, const std::string& graphDir, std::string& display,
                             std::string& text) {
  const std::string quoted = "file '" + source + "'";
  if (source.empty()) return "an empty file path";
  for (char c : source)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return quoted + " contains a control character";
  fs::path rel(source);
  if (rel.is_absolute()) return quoted + " must be relative to the graph file";
  fs::path folded = rel.lexically_normal();
  if (!folded.empty() && *folded.begin() == "..") return quoted + " leaves the graph's folder";
  if (rel.extension() != ".glsl") return quoted + " is not a .glsl file";
  fs::path folder(graphDir.empty() ? "." : graphDir);
  display = (folder / rel).lexically_normal().string();
  std::error_code ec;
  fs::path realFolder = fs::canonical(folder, ec);
  if (ec) return "the graph's folder cannot be resolved: " + ec.message();
  FileReadRule rule;
  rule.maxBytes = kMaxFunctionFileBytes;
  rule.insideFolder = realFolder.string();
  FileReadFailure failure;
  auto read = readFileChecked((folder / rel).string(), rule, &failure);
  if (!read) {
    switch (failure.kind) {
      case FileReadFailure::Kind::Outside: return quoted + " leads outside the graph's folder (through a symbolic link)";
      case FileReadFailure::Kind::TooLarge:
        return quoted + " is larger than " + std::to_string(kMaxFunctionFileBytes) + " bytes, the limit for a function file";
      case FileReadFailure::Kind::NotRegular: return quoted + " is not a regular file";
      default: return quoted + " cannot be read: " + failure.why();
    }
  }
  text = std::move(read->bytes);
  if (text.find('\0') != std::string::npos) return quoted + " holds a NUL byte: it is not GLSL text";
  return "";
}

std::string zeroOf(Type t) {
  if (t == Type::Float) return "0.0";
  return std::string(typeName(t)) + "(0.0)";
}

// The node's GLSL: the out parameters' locals, then one call of the renamed function.
// Each out port reads "(call, local)": the local's value after the call, and a read of the
// call's local, so the planner keeps the call whenever any output is read.
std::function<void(EmitContext&)> emitCall(FunctionSignature sig, std::string renamed) {
  return [sig = std::move(sig), renamed = std::move(renamed)](EmitContext& ctx) {
    std::vector<GlslExpr> args;
    std::vector<std::pair<int, GlslExpr>> outs;  // output port, local
    int input = 0, output = sig.returns == Type::Invalid ? 0 : 1;
    for (const auto& p : sig.parameters) {
      if (p.type == Type::Sampler2D) {
        args.push_back(ctx.texture(p.name));
      } else if (p.out) {
        GlslExpr local = ctx.temporary(p.type, zeroOf(p.type));
        args.push_back(local);
        outs.emplace_back(output++, local);
      } else {
        args.push_back(ctx.input(input++));
      }
    }
    GlslExpr call = renamed + "(";
    for (std::size_t i = 0; i < args.size(); ++i) call += (i ? ", " : "") + args[i];
    call += ")";
    GlslExpr result = sig.returns == Type::Invalid ? ctx.temporary(Type::Float, "(" + call + ", 0.0)")
                                                       : ctx.temporary(sig.returns, call);
    if (sig.returns != Type::Invalid) ctx.output(0, result);
    for (const auto& [port, local] : outs) ctx.output(port, "(" + result + ", " + local + ")");
  };
}

DiagCode codeOf(FunctionCheckFault::Kind k) {
  switch (k) {
    case FunctionCheckFault::Kind::Syntax: return DiagCode::FunctionFileSyntax;
    case FunctionCheckFault::Kind::NoSuchFunction:
    case FunctionCheckFault::Kind::Overloaded: return DiagCode::FunctionNotFound;
    case FunctionCheckFault::Kind::Recursion: return DiagCode::FunctionRecursion;
    case FunctionCheckFault::Kind::ParameterType: return DiagCode::FunctionPortType;
    case FunctionCheckFault::Kind::NameClash: return DiagCode::FunctionNameClash;
  }
  return DiagCode::FunctionFileSyntax;
}

class FunctionNodeMaker {
 public:
  FunctionNodeMaker(const FileNodeRequest& r, Diagnostics& d) : request_(r), node_(r.node), diags_(d) {}

  std::optional<FileNode> run() {
    const NodeOption* file = stringOption("file");
    const NodeOption* function = stringOption("function");
    if (!file || !function) return std::nullopt;
    std::string display, text;
    if (std::string why = readFunctionFile(file->value.get<std::string>(), request_.graphDir, display, text); !why.empty()) {
      diags_.error(DiagCode::FunctionFileUnusable, file->where, "option 'file': " + why, node_.id, "option 'file'");
      return std::nullopt;
    }
    FunctionFileScan scan = scanFunctionFile(text);
    if (scan.fault) {
      bool reserved = scan.fault->message.find("reserved") != std::string::npos;
      return inFile(reserved ? DiagCode::FunctionNameClash : DiagCode::FunctionForbidden, display, scan.fault->where,
                    scan.fault->message, *file);
    }
    const std::string prefix = functionNamespace(request_.namespaceIndex);
    std::string renamed = renameFunctionFile(text, scan.names, prefix);
    const std::string& name = function->value.get_ref<const std::string&>();
    FunctionCheck check = checkFunctionFile(text, display, name, renamed);
    if (check.fault) {
      if (check.fault->kind == FunctionCheckFault::Kind::NoSuchFunction && check.fault->message.find("defines no") != std::string::npos) {
        diags_.error(DiagCode::FunctionNotFound, function->where, "option 'function': " + display + " " + check.fault->message.substr(9),
                     node_.id, "option 'function'");
        return std::nullopt;
      }
      return inFile(codeOf(check.fault->kind), display, check.fault->where, check.fault->message, *file);
    }
    auto spec = std::make_shared<NodeSpec>();
    spec->type = kGlslFunctionType;
    spec->family = "custom";
    spec->summary = "function '" + name + "' of " + display;
    spec->options = glslFunctionOptions();
    std::string firstBuiltin = kBuiltinTexturePrefix.data() + builtinTextureNames().front();
    for (const auto& p : check.signature.parameters) {
      if (p.type == Type::Sampler2D) {
        OptionSpec o;
        o.name = p.name;
        o.kind = OptionSpec::Kind::Texture;
        o.defaultValue = firstBuiltin;
        o.doc = "the texture for sampler2D parameter '" + p.name + "'";
        spec->options.push_back(std::move(o));
        spec->isSource = true;  // it samples a texture: never folded
      } else if (p.out) {
        spec->outputs.push_back({p.name, PortKind::Fixed, p.type});
      } else {
        spec->inputs.push_back({p.name, PortKind::Fixed, p.type});
      }
    }
    if (check.signature.returns != Type::Invalid)
      spec->outputs.insert(spec->outputs.begin(), PortSpec{"out", PortKind::Fixed, check.signature.returns});
    spec->stages = check.signature.fragmentOnly ? kFragmentStage : kAnyStage;
    spec->emit = emitCall(check.signature, prefix + name);
    if (!text.empty() && text.back() != '\n') renamed += '\n';
    spec->ownGlsl = std::make_shared<const std::string>(std::move(renamed));
    if (const NodeOption* reference = writtenOption(node_, "reference")) {
      auto made = makeFunctionReference(check.signature, reference->value);
      if (auto* fault = std::get_if<FunctionReferenceFault>(&made)) {
        diags_.error(fault->syntax ? DiagCode::FormulaSyntax : DiagCode::FormulaType, reference->where,
                     "option 'reference': " + fault->message, node_.id, "option 'reference'");
        return std::nullopt;
      }
      auto& lowered = std::get<FunctionReference>(made);
      spec->eval = std::move(lowered.eval);
      // Held to the bound of the maths its formulas lower into (at least a function's own 1e-5).
      spec->tolerance = std::max(spec->tolerance, lowered.tolerance);
      spec->conditionRoundings = lowered.conditionRoundings;
      if (const NodeOption* roundings = writtenOption(node_, "input_roundings"); roundings && roundings->value.is_number())
        spec->conditionRoundings = std::max(spec->conditionRoundings, roundings->value.get<double>());
    }
    return FileNode{std::move(spec), display};
  }

 private:
  // A Text option the node must write: its value, or null after reporting.
  const NodeOption* stringOption(std::string_view name) {
    const NodeOption* o = writtenOption(node_, name);
    if (!o) {
      diags_.error(DiagCode::MissingField, node_.where,
                   "a glsl_function node needs the option '" + std::string(name) + "'", node_.id);
      return nullptr;
    }
    if (!o->value.is_string()) {
      diags_.error(DiagCode::InvalidOption, o->where, "option '" + std::string(name) + "' must be a string", node_.id,
                   "option '" + std::string(name) + "'");
      return nullptr;
    }
    return o;
  }

  // A fault at its place in the function file, with a note at the node naming the file.
  std::optional<FileNode> inFile(DiagCode code, const std::string& file, FunctionFilePlace where,
                                 const std::string& message, const NodeOption& named) {
    Diagnostic& d = diags_.error(code, SourceRef{file, where.line, where.col}, message, node_.id);
    d.locatedNotes.push_back({named.where, "in the function file of node '" + node_.id + "'", node_.id});
    return std::nullopt;
  }

  const FileNodeRequest& request_;
  const Node& node_;
  Diagnostics& diags_;
};

}  // namespace

std::vector<OptionSpec> glslFunctionOptions() {
  OptionSpec file;
  file.name = "file";
  file.kind = OptionSpec::Kind::Text;
  file.defaultValue = "";
  file.doc = "the .glsl file, relative to the graph file and inside its folder";
  OptionSpec function;
  function.name = "function";
  function.kind = OptionSpec::Kind::Text;
  function.defaultValue = "";
  function.doc = "the function of the file the node calls; its parameters and return value are the ports";
  OptionSpec reference;
  reference.name = "reference";
  reference.kind = OptionSpec::Kind::Json;
  reference.defaultValue = nlohmann::json::object();
  reference.doc = "the double-precision reference: {\"output\": \"formula\"} for every output, formulas in the "
                  "expression language over the inputs; without it the node has no reference";
  reference.validate = [](const nlohmann::json& v) -> std::string {
    return v.is_object() ? "" : "must be an object: {\"output\": \"formula\", ...}";
  };
  OptionSpec roundings;
  roundings.name = "input_roundings";
  roundings.kind = OptionSpec::Kind::Number;
  roundings.defaultValue = 0;
  roundings.min = 0;
  roundings.max = 16;
  roundings.doc = "with a reference: how many float32 roundings of each input the function's float32 arithmetic "
                  "amounts to, the node's input roundings (docs/accuracy.md, the error bound); the bound then grows "
                  "where the formula is ill-conditioned (a sine of a phase past 10^4) and nowhere else";
  return {file, function, reference, roundings};
}

std::optional<FileNode> makeGlslFunctionNode(const FileNodeRequest& request, Diagnostics& diags) {
  return FunctionNodeMaker(request, diags).run();
}

}  // namespace wg
