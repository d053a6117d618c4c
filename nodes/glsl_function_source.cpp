#include "nodes/glsl_function_source.h"

#include <algorithm>
#include <set>

namespace wg {
namespace {

enum class FnTokenKind { Identifier, Number, Punct };

struct FnToken {
  FnTokenKind kind;
  std::size_t offset;
  std::string_view text;
};

bool fnIdentStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool fnIdentChar(char c) { return fnIdentStart(c) || (c >= '0' && c <= '9'); }
bool fnDigit(char c) { return c >= '0' && c <= '9'; }

// The file's tokens, comments and white space skipped. A '#' or '\' is a token of its own
// (the scan refuses both), an unterminated comment ends the text (glslang reports it).
std::vector<FnToken> tokenizeFunctionFile(std::string_view text) {
  std::vector<FnToken> out;
  std::size_t i = 0, n = text.size();
  while (i < n) {
    char c = text[i];
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') {
      ++i;
    } else if (text.compare(i, 2, "//") == 0) {
      std::size_t eol = text.find('\n', i);
      i = eol == std::string_view::npos ? n : eol + 1;
    } else if (text.compare(i, 2, "/*") == 0) {
      std::size_t end = text.find("*/", i + 2);
      i = end == std::string_view::npos ? n : end + 2;
    } else if (fnIdentStart(c)) {
      std::size_t b = i;
      while (i < n && fnIdentChar(text[i])) ++i;
      out.push_back({FnTokenKind::Identifier, b, text.substr(b, i - b)});
    } else if (fnDigit(c) || (c == '.' && i + 1 < n && fnDigit(text[i + 1]))) {
      std::size_t b = i;
      while (i < n) {
        char d = text[i];
        bool exponentSign = (d == '+' || d == '-') && (text[i - 1] == 'e' || text[i - 1] == 'E') &&
                            !(text.size() > b + 1 && text[b] == '0' && (text[b + 1] == 'x' || text[b + 1] == 'X'));
        if (!(fnIdentChar(d) || d == '.' || exponentSign)) break;
        ++i;
      }
      out.push_back({FnTokenKind::Number, b, text.substr(b, i - b)});
    } else {
      out.push_back({FnTokenKind::Punct, i, text.substr(i, 1)});
      ++i;
    }
  }
  return out;
}

// Qualifiers and keywords a function file may not use at its top level: they declare
// what the generated shader declares (its interface, its precision, its layout) or types
// a port cannot carry.
const std::set<std::string_view>& forbiddenTopLevelWords() {
  static const std::set<std::string_view> words = {
      "uniform", "in",    "out",    "inout",         "attribute", "varying", "buffer",     "shared",
      "layout",  "precision", "invariant", "centroid", "flat",  "smooth",  "noperspective", "patch",
      "sample",  "subroutine", "struct", "precise"};
  return words;
}

// Names the generated shader uses for itself; a file may not use them in any form, so no
// name of the file can meet one after renaming.
std::optional<std::string> reservedNameWhy(std::string_view name) {
  auto starts = [&](std::string_view p) { return name.substr(0, p.size()) == p; };
  if (starts("wg_") || starts("WG_") || starts("wgfn"))
    return "the name '" + std::string(name) +
           "' is reserved: names beginning with 'wg_', 'WG_' or 'wgfn' are the generated shader's, and a file's own "
           "names are renamed into 'wgfn<k>_...' (it would clash after renaming)";
  if (name == "main") return std::string("the file may not declare 'main': the generated shader declares it");
  return std::nullopt;
}

class FunctionFileScanner {
 public:
  explicit FunctionFileScanner(std::string_view text) : text_(text), tokens_(tokenizeFunctionFile(text)) {}

  FunctionFileScan run() {
    for (const FnToken& t : tokens_) {
      if (t.text == "#") {
        std::string word;
        if (&t + 1 < tokens_.data() + tokens_.size() && (&t + 1)->kind == FnTokenKind::Identifier) word = (&t + 1)->text;
        return fail(t, word == "version" || word == "extension"
                           ? "'#" + word + "' is not accepted: the generated shader declares the version and extensions for each target"
                           : std::string("preprocessor lines are not accepted (write a constant as 'const float K = ...;')"));
      }
      if (t.text == "\\") return fail(t, "a backslash (line continuation) is not accepted");
      if (t.kind == FnTokenKind::Identifier)
        if (auto why = reservedNameWhy(t.text); why && t.text != "main") return fail(t, *why);
    }
    std::size_t i = 0;
    while (i < tokens_.size() && !scan_.fault) i = statement(i);
    return std::move(scan_);
  }

 private:
  FunctionFileScan fail(const FnToken& t, std::string message) {
    scan_.fault = FunctionFileFault{placeInText(text_, t.offset), std::move(message)};
    return std::move(scan_);
  }
  void refuse(const FnToken& t, std::string message) {
    if (!scan_.fault) scan_.fault = FunctionFileFault{placeInText(text_, t.offset), std::move(message)};
  }

  // One top-level statement from token `i`: a function (definition or prototype) or a
  // declaration; returns the index after it.
  std::size_t statement(std::size_t i) {
    const std::size_t start = i;
    int parens = 0;
    std::size_t firstParen = std::string_view::npos, firstEquals = std::string_view::npos;
    for (; i < tokens_.size(); ++i) {
      const FnToken& t = tokens_[i];
      if (t.text == "(" || t.text == "[") ++parens;
      else if (t.text == ")" || t.text == "]") --parens;
      if (parens != 0 && !(parens == 1 && t.text == "(")) continue;
      if (t.text == "(" && firstParen == std::string_view::npos && firstEquals == std::string_view::npos) firstParen = i;
      if (t.text == "=" && firstEquals == std::string_view::npos) firstEquals = i;
      if (t.kind == FnTokenKind::Identifier && parens == 0 && forbiddenTopLevelWords().count(t.text)) {
        refuse(t, forbiddenWhy(t.text));
        return tokens_.size();
      }
      if (parens == 0 && (t.text == ";" || t.text == "{")) break;
    }
    if (i >= tokens_.size()) {
      if (start < tokens_.size()) refuse(tokens_[start], "this declaration does not end (a ';' or a function body is missing)");
      return tokens_.size();
    }
    if (i == start) return i + 1;  // an empty statement
    if (firstParen != std::string_view::npos) {
      function(start, firstParen);
      return tokens_[i].text == "{" ? skipBody(i) : i + 1;
    }
    if (tokens_[i].text == "{") {
      refuse(tokens_[i], "a block outside a function");
      return tokens_.size();
    }
    constant(start, i);
    return i + 1;
  }

  std::string forbiddenWhy(std::string_view word) const {
    if (word == "struct") return "a struct is not accepted: a function file holds functions over float, vecN and matN";
    if (word == "precision") return "a precision statement is not accepted: the generated shader sets the precision for each target";
    return "'" + std::string(word) +
           "' is not accepted at the top level: the generated shader declares the uniforms, inputs, outputs and "
           "layouts; a function takes what it needs as parameters";
  }

  void function(std::size_t start, std::size_t paren) {
    if (paren == start || tokens_[paren - 1].kind != FnTokenKind::Identifier) {
      refuse(tokens_[paren], "expected a function declaration: a type, a name and its parameters");
      return;
    }
    const FnToken& name = tokens_[paren - 1];
    if (name.text == "main") return refuse(name, *reservedNameWhy("main"));
    auto& fns = scan_.names.functions;
    if (std::find(fns.begin(), fns.end(), name.text) == fns.end()) fns.emplace_back(name.text);
  }

  // A global: only constants ("const float K = 2.0, L = 3.0;").
  void constant(std::size_t start, std::size_t end) {
    if (tokens_[start].text != "const") {
      refuse(tokens_[start],
             "a global variable must be a constant ('const'): a node keeps no state between calls");
      return;
    }
    // Declarators, split at top-level commas: the name is the last identifier before '='
    // or '[' in the first (after the type), the first identifier in the others.
    int depth = 0;
    bool first = true, inInitialiser = false, named = false;
    const FnToken* last = nullptr;
    auto take = [&](const FnToken* t) {
      if (!t) return;
      if (t->text == "main") return refuse(*t, *reservedNameWhy("main"));
      scan_.names.constants.emplace_back(t->text);
    };
    for (std::size_t i = start + 1; i < end; ++i) {
      const FnToken& t = tokens_[i];
      if (t.text == "(" || t.text == "[" || t.text == "{") ++depth;
      if (t.text == ")" || t.text == "]" || t.text == "}") --depth;
      if (depth == 0 && t.text == ",") {
        if (!named) take(last);
        first = false, inInitialiser = false, named = false, last = nullptr;
        continue;
      }
      if (inInitialiser) continue;
      if ((t.text == "=" || t.text == "[") && depth <= 1) {
        if (!named) take(last);
        named = true;
        if (t.text == "=") inInitialiser = true;
        continue;
      }
      if (t.kind == FnTokenKind::Identifier && depth == 0 && !named) {
        last = &t;
        if (!first) {
          take(last);
          named = true;
        }
      }
    }
    if (!named) take(last);
  }

  std::size_t skipBody(std::size_t open) {
    int depth = 0;
    for (std::size_t i = open; i < tokens_.size(); ++i) {
      if (tokens_[i].text == "{") ++depth;
      if (tokens_[i].text == "}" && --depth == 0) return i + 1;
    }
    refuse(tokens_[open], "this function body does not end (a '}' is missing)");
    return tokens_.size();
  }

  std::string_view text_;
  std::vector<FnToken> tokens_;
  FunctionFileScan scan_;
};

}  // namespace

FunctionFilePlace placeInText(std::string_view text, std::size_t offset) {
  FunctionFilePlace p;
  std::size_t lineStart = 0;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i)
    if (text[i] == '\n') {
      ++p.line;
      lineStart = i + 1;
    }
  p.col = static_cast<int>(offset - lineStart) + 1;
  return p;
}

FunctionFileScan scanFunctionFile(std::string_view text) { return FunctionFileScanner(text).run(); }

std::string functionNamespace(int k) { return "wgfn" + std::to_string(k) + "_"; }

std::string renameFunctionFile(std::string_view text, const FunctionFileNames& names, const std::string& prefix) {
  std::set<std::string_view> renamed(names.functions.begin(), names.functions.end());
  renamed.insert(names.constants.begin(), names.constants.end());
  std::string out;
  out.reserve(text.size() + text.size() / 8);
  std::size_t copied = 0;
  const FnToken* previous = nullptr;
  std::vector<FnToken> tokens = tokenizeFunctionFile(text);
  for (const FnToken& t : tokens) {
    bool member = previous && previous->text == ".";
    if (t.kind == FnTokenKind::Identifier && !member && renamed.count(t.text)) {
      out.append(text.substr(copied, t.offset - copied));
      out += prefix;
      out.append(t.text);
      copied = t.offset + t.text.size();
    }
    previous = &t;
  }
  out.append(text.substr(copied));
  return out;
}

}  // namespace wg
