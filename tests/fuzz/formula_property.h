#pragma once
// The property of the formula fuzz target (fuzz_formula.cpp), kept here so the ordinary
// test suite can replay saved inputs through it. The fuzz bytes are an `expression`
// node's formula over the inputs a (float), b (vec2), c (vec3) and d (vec4), put into a
// graph file as a JSON string (escaped by the JSON writer, so the file columns of its
// characters differ from their offsets). The property: the formula parses and types
// exactly when the graph compiles (for every target, glslang accepting the code); when it
// does not, the first error is one WG037/WG038 whose line is the formula's and whose
// column lies on the formula's string, between its quotes.
#include <string>
#include <string_view>
#include <variant>

#include <nlohmann/json.hpp>

#include "core/expression_parser.h"
#include "core/expression_types.h"
#include "core/load_limits.h"
#include "core/text_lines.h"
#include "fuzz_properties.h"

namespace wg::fuzz {

// The graph, with the formula alone on line 8 after `    "formula": ` (its quote at column 16).
inline std::string formulaGraph(std::string_view formula, Type type) {
  // The JSON writer escapes what JSON needs (and replaces bytes that are not UTF-8), so
  // the file always loads.
  std::string quoted = nlohmann::json(std::string(formula)).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  const char* toColor = type == Type::Float ? "vec3(x)" : type == Type::Vec2 ? "vec3(x, 0.5)" : type == Type::Vec4 ? "x.rgb" : "x";
  std::string xType = type == Type::Invalid || type == Type::Bool ? "vec3" : std::string(typeName(type));
  return "{\n"
         "  \"version\": 1, \"name\": \"formula\",\n"
         "  \"parameters\": {\"a\": {\"type\": \"float\", \"default\": 0.5}, \"b\": {\"type\": \"vec2\", \"default\": [0.5, -1]},\n"
         "                 \"c\": {\"type\": \"vec3\", \"default\": [0.1, 0.2, 0.3]}, \"d\": {\"type\": \"vec4\", \"default\": [1, 2, 3, 4]}},\n"
         "  \"nodes\": [\n"
         "   {\"id\": \"e\", \"type\": \"expression\", \"inputs\": {\"a\": \"$a\", \"b\": \"$b\", \"c\": \"$c\", \"d\": \"$d\"},\n"
         "    \"options\": {\"inputs\": {\"a\": \"float\", \"b\": \"vec2\", \"c\": \"vec3\", \"d\": \"vec4\"},\n"
         "    \"formula\": " + quoted + "}},\n"
         "   {\"id\": \"f\", \"type\": \"expression\", \"inputs\": {\"x\": \"e.out\"},\n"
         "    \"options\": {\"inputs\": {\"x\": \"" + xType + "\"}, \"formula\": \"" + toColor + "\"}}],\n"
         "  \"outputs\": {\"fragment\": {\"color\": \"f.out\"}}\n"
         "}\n";
}

inline std::string formulaProperty(std::string_view formula) {
  const expr::FormulaInputs inputs = {{"a", Type::Float}, {"b", Type::Vec2}, {"c", Type::Vec3}, {"d", Type::Vec4}};
  // What the formula is, by the library alone.
  Type type = Type::Invalid;
  auto parsed = expr::parseFormula(formula);
  if (const auto* ast = std::get_if<expr::Ast>(&parsed)) {
    auto typed = expr::typeFormula(*ast, inputs);
    if (const auto* types = std::get_if<std::vector<Type>>(&typed)) type = types->at(static_cast<size_t>(ast->root));
  }
  std::string text = formulaGraph(formula, type);
  bool wellFormed = type != Type::Invalid && formula.size() <= kMaxStringBytes &&
                    formula.find_first_of(std::string_view("\0", 1)) == std::string_view::npos;
  if (wellFormed) {
    // Bytes that are not UTF-8 are replaced in the file: the library's verdict was on others.
    nlohmann::json j = std::string(formula);
    wellFormed = j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) == j.dump(-1, ' ', false, nlohmann::json::error_handler_t::ignore);
  }
  std::string pipeline = pipelineProperty(text);
  if (!pipeline.empty()) return pipeline + "\n" + text;
  Diagnostics diags;
  auto graph = parseGraph(text, "fuzz.json", diags);
  if (!graph) return wellFormed ? failure("a well-formed formula's graph does not load\n" + text, diags) : "";
  auto program = buildProgram(*graph, defaultRegistry(), diags);
  if (wellFormed) return program ? "" : failure("a formula the library accepts does not compile\n" + text, diags);
  if (program) return formula.size() > kMaxStringBytes ? "" : failure("a formula the library refuses compiles\n" + text, diags);
  std::vector<Diagnostic> sorted = diags.sorted();
  const Diagnostic& first = sorted.front();
  if (first.code == DiagCode::LimitExceeded) return "";  // a formula string over the format's limit
  if (first.code != DiagCode::FormulaSyntax && first.code != DiagCode::FormulaType)
    return failure("a faulty formula's first error is not WG037/WG038\n" + text, diags);
  const int line = 8, quoteColumn = 16;
  std::string_view lineText = splitLines(text).at(line - 1);
  int closingColumn = static_cast<int>(lineText.rfind("}}"));  // the closing quote is just before "}}"
  if (first.where.line != line || first.where.col <= quoteColumn || first.where.col > closingColumn)
    return failure("a formula error placed off the formula's string (quote at column 16, closing quote at " +
                       std::to_string(closingColumn) + ")\n" + text, diags);
  return "";
}

}  // namespace wg::fuzz
