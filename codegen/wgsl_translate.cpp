// The GLSL subset printed as WGSL: the library's items statement by statement, the plan's
// statements expression by expression (see codegen/wgsl_translate.h for the rules kept).
// Expressions are printed by codegen/wgsl_expressions.cpp.
#include "codegen/wgsl_translate.h"

#include <stdexcept>

#include "codegen/glsl_subset.h"
#include "codegen/wgsl_expressions.h"
#include "nodes/glsl_library.h"

namespace wg::wgsl {

using glsl_subset::Expr;
using glsl_subset::Stmt;

void Translator::declareGlobal(const std::string& name, ValueType type, std::string wgsl) {
  globalTypes_[name] = type;
  globalText_[name] = std::move(wgsl);
}

void Translator::declareSampler(const std::string& name, ValueType type, std::string texture, std::string sampler) {
  globalTypes_[name] = type;
  samplers_[name] = {std::move(texture), std::move(sampler)};
}

std::string modHelperName(const ValueType& t) {
  return "wgsl_mod_" + (t.size == 1 ? std::string("f32") : "vec" + std::to_string(t.size) + "f");
}

namespace {

// The names a statement list assigns to (=, op=, ++, --), by the root of the assigned expression.
void collectAssigned(const Expr& e, std::set<std::string>& out) {
  auto root = [](const Expr* x) {
    while (x->kind == Expr::Kind::Member || x->kind == Expr::Kind::Index) x = x->args[0].get();
    return x->kind == Expr::Kind::Name ? x->text : std::string();
  };
  bool increments = (e.kind == Expr::Kind::Unary && (e.text == "++" || e.text == "--")) || e.kind == Expr::Kind::Postfix;
  if (e.kind == Expr::Kind::Assign || increments) out.insert(root(e.args[0].get()));
  for (const auto& a : e.args) collectAssigned(*a, out);
}

void collectAssigned(const Stmt& s, std::set<std::string>& out) {
  if (s.expr) collectAssigned(*s.expr, out);
  for (const auto& d : s.declared)
    if (d.init) collectAssigned(*d.init, out);
  for (const auto& b : s.body)
    if (b) collectAssigned(*b, out);
}

}  // namespace

// Prints statements with a scope stack: the library items' functions and constants, and the
// planned statements' expressions (whose names are the entry point's locals and the globals).
class TranslationContext : public ExpressionPrinter {
 public:
  TranslationContext(Translator& t, StageMode mode) : t_(t), mode_(mode) { scopes_.emplace_back(); }

  std::string statement(const Stmt& s, const std::string& indent) {
    switch (s.kind) {
      case Stmt::Kind::Empty: return "";
      case Stmt::Kind::Block: {
        std::string out = indent + "{\n" + block(s.body, indent + "  ");
        return out + indent + "}\n";
      }
      case Stmt::Kind::Declare: {
        ValueType type = glslType(s.type);
        std::string out;
        for (const auto& d : s.declared) {
          std::string name = wgslSafeName(d.name);
          std::string init;
          if (d.init) init = " = " + converted(*d.init, type);
          out += indent + (s.isConst ? "let " : "var ") + name + ": " + wgslTypeName(type) + init + ";\n";
          scopes_.back()[d.name] = {type, name};
        }
        return out;
      }
      case Stmt::Kind::Expression: return indent + expressionStatement(*s.expr) + ";\n";
      case Stmt::Kind::If: {
        std::string cond = expression(*s.expr).text;
        tainted_ = true;
        std::string out = indent + "if " + parenthesised(cond) + " {\n" + nested(*s.body[0], indent + "  ");
        if (s.body[1]) out += indent + "} else {\n" + nested(*s.body[1], indent + "  ");
        return out + indent + "}\n";
      }
      case Stmt::Kind::For: {
        scopes_.emplace_back();
        const Stmt& init = *s.body[0];
        std::string initText = statement(init, "");
        if (!initText.empty()) initText.erase(initText.size() - 2);  // ";\n"
        tainted_ = true;
        std::string cond = s.expr ? expression(*s.expr).text : "true";
        std::string step = s.body[1]->expr ? expressionStatement(*s.body[1]->expr) : "";
        std::string out = indent + "for (" + initText + "; " + cond + "; " + step + ") {\n" +
                          nested(*s.body[2], indent + "  ") + indent + "}\n";
        scopes_.pop_back();
        return out;
      }
      case Stmt::Kind::While: {
        tainted_ = true;
        std::string cond = expression(*s.expr).text;
        return indent + "while " + parenthesised(cond) + " {\n" + nested(*s.body[0], indent + "  ") + indent + "}\n";
      }
      case Stmt::Kind::Return:
        return indent + "return" + (s.expr ? " " + converted(*s.expr, returnType_) : "") + ";\n";
      case Stmt::Kind::Break: return indent + "break;\n";
      case Stmt::Kind::Continue: return indent + "continue;\n";
      case Stmt::Kind::Discard: return indent + "discard;\n";
    }
    return "";
  }

  std::string function(const glsl_subset::Function& f, const std::vector<std::string>& comments) {
    for (const auto& p : f.params)
      if (!p.qualifier.empty() && p.qualifier != "in")
        throw std::logic_error("GLSL subset: '" + p.qualifier + "' parameter in " + f.name);
    std::set<std::string> assigned;
    for (const auto& s : f.body) collectAssigned(*s, assigned);
    returnType_ = glslType(f.returnType);
    std::string params, copies;
    Translator::FunctionInfo info;
    info.result = returnType_;
    for (const auto& p : f.params) {
      ValueType type = glslType(p.type);
      info.params.push_back(type);
      std::string name = wgslSafeName(p.name);
      if (!params.empty()) params += ", ";
      if (type.isSampler()) {
        params += name + "_texture: " + wgslTypeName(type) + ", " + name + "_sampler: sampler";
        localSamplers_[p.name] = {name + "_texture", name + "_sampler"};
        scopes_.back()[p.name] = {type, name};
        continue;
      }
      if (assigned.count(p.name)) {
        params += name + "_in: " + wgslTypeName(type);
        copies += "  var " + name + ": " + wgslTypeName(type) + " = " + name + "_in;\n";
      } else {
        params += name + ": " + wgslTypeName(type);
      }
      scopes_.back()[p.name] = {type, name};
    }
    std::string body = block(f.body, "  ");
    info.samples = samples_;
    std::string wgslName = functionName(f.name, info.samples);
    std::string out;
    for (const auto& c : comments) out += c + "\n";
    out += "fn " + wgslName + "(" + params + ")" + (returnType_.base == 'v' ? "" : " -> " + wgslTypeName(returnType_)) +
           " {\n" + copies + body + "}\n";
    t_.functions_[f.name] = info;
    return out;
  }

  // The vertex mode writes the level-0 form of a function that samples with an implicit LOD.
  std::string functionName(const std::string& glslName, bool samples) const {
    return mode_ == StageMode::Vertex && samples ? glslName + kLod0Suffix : glslName;
  }

 protected:
  // ExpressionPrinter's view of the names in scope.
  std::optional<Symbol> lookup(const std::string& name) const override {
    for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it) {
      auto f = it->find(name);
      if (f != it->end()) {
        Symbol s{f->second.type, f->second.wgsl, "", ""};
        if (auto sm = localSamplers_.find(name); sm != localSamplers_.end()) {
          s.texture = sm->second.first;
          s.sampler = sm->second.second;
        }
        return s;
      }
    }
    if (auto l = t_.locals_.find(name); l != t_.locals_.end()) return Symbol{l->second.type, l->second.wgsl, "", ""};
    if (auto g = t_.globalTypes_.find(name); g != t_.globalTypes_.end()) {
      Symbol s{g->second, "", "", ""};
      if (auto sm = t_.samplers_.find(name); sm != t_.samplers_.end()) {
        s.texture = sm->second.first;
        s.sampler = sm->second.second;
      } else {
        s.wgsl = t_.globalText_.at(name);
      }
      return s;
    }
    if (auto c = t_.constants_.find(name); c != t_.constants_.end()) return Symbol{c->second, name, "", ""};
    return std::nullopt;
  }
  std::optional<Callee> callee(const std::string& name) const override {
    auto f = t_.functions_.find(name);
    if (f == t_.functions_.end()) return std::nullopt;
    return Callee{f->second.result, f->second.params, name, f->second.samples};
  }
  bool vertexStage() const override { return mode_ == StageMode::Vertex; }
  void useModHelper(const ValueType& t) override { t_.helpers_.insert(wgslTypeName(t)); }
  void noteImplicitSample() override { samples_ = true; }

 private:
  struct Local {
    ValueType type;
    std::string wgsl;
  };

  std::string block(const std::vector<glsl_subset::StmtPtr>& body, const std::string& indent) {
    scopes_.emplace_back();
    std::string out;
    for (const auto& s : body) out += statement(*s, indent);
    scopes_.pop_back();
    return out;
  }

  // A statement that is the body of an if/for/while: its block's statements, not a block in a block.
  std::string nested(const Stmt& s, const std::string& indent) {
    if (s.kind == Stmt::Kind::Block) return block(s.body, indent);
    scopes_.emplace_back();
    std::string out = statement(s, indent);
    scopes_.pop_back();
    return out;
  }

  static std::string parenthesised(const std::string& e) {
    return !e.empty() && e.front() == '(' && e.back() == ')' ? e : "(" + e + ")";
  }

  Translator& t_;
  StageMode mode_;
  std::vector<std::map<std::string, Local>> scopes_;
  std::map<std::string, std::pair<std::string, std::string>> localSamplers_;
  ValueType returnType_;
  bool samples_ = false;
};

void Translator::addItem(const GlslItem& item, StageMode mode) {
  std::vector<glsl_subset::Item> parsed;
  try {
    parsed = glsl_subset::parseItems(item.text);
  } catch (const std::logic_error& e) {
    throw std::logic_error(std::string(e.what()) + " (library item " + item.name + ", nodes/glsl/" + item.file + ".glsl)");
  }
  for (const auto& p : parsed) {
    if (p.constant) {
      ValueType type = glslType(p.constant->type);
      constants_[p.constant->name] = type;
      if (!emitted_.insert(p.constant->name).second) continue;
      TranslationContext ctx(*this, mode);
      std::string out;
      for (const auto& c : p.leadingComments) out += c + "\n";
      out += "const " + p.constant->name + ": " + wgslTypeName(type) + " = " + ctx.converted(*p.constant->value, type) + ";\n";
      items_.push_back(out);
      continue;
    }
    // Its form for `mode`; one that samples with an implicit LOD in the fragment stage also
    // gets its level-0 form, called from the vertex stage and under non-uniform control flow.
    for (StageMode m : {mode, StageMode::Vertex}) {
      TranslationContext ctx(*this, m);
      std::string text;
      try {
        text = ctx.function(*p.function, p.leadingComments);
      } catch (const std::logic_error& e) {
        throw std::logic_error(std::string(e.what()) + " (library item " + item.name + ", nodes/glsl/" + item.file + ".glsl)");
      }
      bool samples = functions_[p.function->name].samples;
      if (emitted_.insert(ctx.functionName(p.function->name, samples)).second) items_.push_back(text);
      if (!samples) break;
    }
  }
}

std::string Translator::declareLocal(const std::string& name, ValueType type) {
  Local& local = locals_[name];
  local = {type, wgslSafeName(name)};
  return local.wgsl;
}

std::string Translator::expression(std::string_view glsl, StageMode mode, ValueType expected) {
  const glsl_subset::ExprPtr parsed = glsl_subset::parseExpression(glsl);
  TranslationContext ctx(*this, mode);
  return ctx.converted(*parsed, expected);
}

std::string Translator::assignment(const std::string& name, std::string_view glsl, StageMode mode) {
  std::string target;
  ValueType type;
  if (auto l = locals_.find(name); l != locals_.end()) {
    target = l->second.wgsl;
    type = l->second.type;
  } else if (auto g = globalText_.find(name); g != globalText_.end()) {
    target = g->second;
    type = globalTypes_.at(name);
  } else {
    throw std::logic_error("GLSL subset: an assignment to '" + name + "', which is not a declared name");
  }
  return target + " = " + expression(glsl, mode, type);
}

std::string Translator::functionsText() const {
  std::string out;
  for (const auto& h : helpers_) {
    ValueType t = h == "f32" ? ValueType{'f', 1, 0} : ValueType{'f', h[3] - '0', 0};
    out += "// GLSL's mod: x - y * floor(x / y) (WGSL's % truncates).\n";
    out += "fn " + modHelperName(t) + "(x: " + h + ", y: " + h + ") -> " + h + " { return x - y * floor(x / y); }\n\n";
  }
  for (const auto& i : items_) out += i + "\n";
  return out;
}

}  // namespace wg::wgsl
