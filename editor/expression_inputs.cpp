#include "editor/expression_inputs.h"

#include <algorithm>
#include <optional>

#include "core/expression_lexer.h"
#include "core/graph_node_type.h"

namespace wg::editor {
namespace {

constexpr const char* kExpressionType = "expression";

// The node's written value of `option`, or the expression type's default.
nlohmann::json expressionOption(const Node& n, const NodeSpec& spec, const std::string& option) {
  for (const NodeOption& o : n.options)
    if (o.name == option) return o.value;
  int index = spec.optionIndex(option);
  return index < 0 ? nlohmann::json() : spec.options[static_cast<size_t>(index)].defaultValue;
}

// The expression node `id`, or why it is not one.
struct ExpressionNode {
  const Node* node = nullptr;
  const NodeSpec* spec = nullptr;
  nlohmann::json declared;  // {"name": "type"}
  std::string formula;
};

std::optional<ExpressionNode> findExpression(const GraphEditor& editor, const Registry& registry, const std::string& id,
                                             std::string* why) {
  const Node* n = editor.graph().findNode(id);
  if (!n) return *why = "no node '" + id + "'", std::nullopt;
  GraphNodeType type = nodeTypeOf(editor.graph(), registry, n->type);
  if (!type.spec || type.spec->type != kExpressionType)
    return *why = "node '" + id + "' is a " + n->type + ", not an expression", std::nullopt;
  ExpressionNode e{n, type.spec, expressionOption(*n, *type.spec, "inputs"), {}};
  nlohmann::json formula = expressionOption(*n, *type.spec, "formula");
  if (!e.declared.is_object()) return *why = "node '" + id + "': its 'inputs' option is not an object; fix it in the JSON field", std::nullopt;
  if (formula.is_string()) e.formula = formula.get<std::string>();
  return e;
}

void setExpressionOption(Node& n, const std::string& file, const std::string& name, nlohmann::json value) {
  for (NodeOption& o : n.options)
    if (o.name == name) {
      o.value = std::move(value);
      return;
    }
  NodeOption o;
  o.name = name;
  o.value = std::move(value);
  o.where.file = o.keyWhere.file = file;
  n.options.push_back(std::move(o));
}

// The declared inputs with `edit` applied, checked as the node checks them, then made the
// graph's (one undo step labelled `label`).
template <typename Edit>
std::string editDeclared(GraphEditor& editor, const Registry& registry, const std::string& id, const std::string& label,
                         const Edit& edit) {
  std::string why;
  std::optional<ExpressionNode> e = findExpression(editor, registry, id, &why);
  if (!e) return why;
  Graph g = editor.graph();
  Node& n = *std::find_if(g.nodes.begin(), g.nodes.end(), [&](const Node& m) { return m.id == id; });
  nlohmann::json declared = e->declared;
  std::string formula = e->formula;
  if (std::string refused = edit(declared, formula, n); !refused.empty()) return refused;
  const OptionSpec& inputs = e->spec->options[static_cast<size_t>(e->spec->optionIndex("inputs"))];
  if (inputs.validate)
    if (std::string bad = inputs.validate(declared); !bad.empty()) return "the inputs " + bad;
  setExpressionOption(n, g.file, "inputs", std::move(declared));
  if (formula != e->formula) setExpressionOption(n, g.file, "formula", std::move(formula));
  editor.replace(std::move(g), label + " of node '" + id + "'");
  return "";
}

}  // namespace

std::string renameFormulaReferences(const std::string& formula, const std::string& from, const std::string& to,
                                    std::string* renamed) {
  std::optional<expr::FormulaError> error;
  std::vector<expr::Token> tokens = expr::tokenize(formula, &error);
  if (error) return "the formula does not read as tokens (" + error->message + "); fix it first";
  std::string out;
  size_t copied = 0;
  for (size_t i = 0; i < tokens.size(); ++i) {
    const expr::Token& t = tokens[i];
    if (t.kind != expr::TokenKind::Identifier || t.text != from) continue;
    bool swizzle = i > 0 && tokens[i - 1].kind == expr::TokenKind::Symbol && tokens[i - 1].text == ".";
    bool call = i + 1 < tokens.size() && tokens[i + 1].kind == expr::TokenKind::Symbol && tokens[i + 1].text == "(";
    if (swizzle || call) continue;
    out.append(formula, copied, t.span.offset - copied);
    out += to;
    copied = t.span.offset + t.span.length;
  }
  out.append(formula, copied, std::string::npos);
  *renamed = std::move(out);
  return "";
}

std::string declareExpressionInput(GraphEditor& editor, const Registry& registry, const std::string& node,
                                   const std::string& name, Type type) {
  return editDeclared(editor, registry, node, "declare input '" + name + "'", [&](nlohmann::json& declared, std::string&, Node&) {
    if (!isIdentifier(name)) return "'" + name + "' is not an identifier ([A-Za-z_][A-Za-z0-9_]*, at most 64)";
    if (declared.contains(name)) return "an input '" + name + "' is already declared";
    declared[name] = std::string(typeName(type));
    return std::string();
  });
}

std::string retypeExpressionInput(GraphEditor& editor, const Registry& registry, const std::string& node,
                                  const std::string& name, Type type) {
  return editDeclared(editor, registry, node, "make input '" + name + "' a " + std::string(typeName(type)),
                      [&](nlohmann::json& declared, std::string&, Node&) {
                        if (!declared.contains(name)) return "no input '" + name + "' is declared";
                        declared[name] = std::string(typeName(type));
                        return std::string();
                      });
}

std::string renameExpressionInput(GraphEditor& editor, const Registry& registry, const std::string& node,
                                  const std::string& from, const std::string& to) {
  return editDeclared(editor, registry, node, "rename input '" + from + "' to '" + to + "'",
                      [&](nlohmann::json& declared, std::string& formula, Node& n) {
                        if (!declared.contains(from)) return "no input '" + from + "' is declared";
                        if (!isIdentifier(to)) return "'" + to + "' is not an identifier ([A-Za-z_][A-Za-z0-9_]*, at most 64)";
                        if (to == from) return std::string("the name is unchanged");
                        if (declared.contains(to)) return "an input '" + to + "' is already declared";
                        std::string renamed;
                        if (std::string why = renameFormulaReferences(formula, from, to, &renamed); !why.empty()) return why;
                        formula = std::move(renamed);
                        declared[to] = declared[from];
                        declared.erase(from);
                        for (NodeInput& in : n.inputs)
                          if (in.port == from) in.port = to;
                        return std::string();
                      });
}

std::string removeExpressionInput(GraphEditor& editor, const Registry& registry, const std::string& node,
                                  const std::string& name) {
  return editDeclared(editor, registry, node, "remove input '" + name + "'", [&](nlohmann::json& declared, std::string&, Node& n) {
    if (!declared.contains(name)) return "no input '" + name + "' is declared";
    declared.erase(name);
    std::erase_if(n.inputs, [&](const NodeInput& in) { return in.port == name; });
    return std::string();
  });
}

}  // namespace wg::editor
