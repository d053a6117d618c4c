#pragma once
// Diagnostics with stable codes from one catalogue (core/diagnostic_codes.def), printed
// as `file:line:col: error: [WG029] message (node 'n', input 'p')` or as JSON.
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/source_ref.h"

namespace wg {

enum class DiagCode : int {
#define WG_DIAG(name, number, summary) name = number,
#include "core/diagnostic_codes.def"
#undef WG_DIAG
};

struct DiagCodeInfo {
  DiagCode code;
  std::string_view enumerator;
  std::string_view summary;
};
const std::vector<DiagCodeInfo>& diagnosticCatalogue();
std::string codeString(DiagCode code);  // "WG029"

enum class Severity { Error, Warning, Note };

struct Diagnostic {
  DiagCode code{};
  Severity severity = Severity::Error;
  std::string message;
  SourceRef where;
  std::string node;  // node id, when one is involved
  std::string port;  // "input 'normal'", "option 'model'", "output 'color'"
  std::vector<std::string> notes;
};

class Diagnostics {
 public:
  Diagnostic& error(DiagCode code, SourceRef where, std::string message, std::string node = {},
                    std::string port = {});
  Diagnostic& warning(DiagCode code, SourceRef where, std::string message, std::string node = {},
                      std::string port = {});
  void add(Diagnostic d) { list_.push_back(std::move(d)); }
  void append(const Diagnostics& other);
  bool hasErrors() const;
  size_t errorCount() const;
  const std::vector<Diagnostic>& all() const { return list_; }
  bool empty() const { return list_.empty(); }
  // Stable order for printing: by file, line, column, then insertion.
  std::vector<Diagnostic> sorted() const;

 private:
  std::vector<Diagnostic> list_;
};

std::string formatText(const Diagnostic& d);
nlohmann::json toJson(const Diagnostic& d);

}  // namespace wg
