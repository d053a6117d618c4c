#include "core/diagnostic.h"

#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>

namespace wg {

const std::vector<DiagCodeInfo>& diagnosticCatalogue() {
  static const std::vector<DiagCodeInfo> catalogue = {
#define WG_DIAG(name, number, summary) {DiagCode::name, #name, summary},
#include "core/diagnostic_codes.def"
#undef WG_DIAG
  };
  return catalogue;
}

std::string codeString(DiagCode code) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "WG%03d", static_cast<int>(code));
  return buf;
}

Diagnostic& Diagnostics::error(DiagCode code, SourceRef where, std::string message, std::string node,
                               std::string port) {
  list_.push_back({code, Severity::Error, std::move(message), std::move(where), std::move(node),
                   std::move(port), {}});
  return list_.back();
}

Diagnostic& Diagnostics::warning(DiagCode code, SourceRef where, std::string message,
                                 std::string node, std::string port) {
  list_.push_back({code, Severity::Warning, std::move(message), std::move(where), std::move(node),
                   std::move(port), {}});
  return list_.back();
}

void Diagnostics::append(const Diagnostics& other) {
  list_.insert(list_.end(), other.list_.begin(), other.list_.end());
}

bool Diagnostics::hasErrors() const { return errorCount() > 0; }

size_t Diagnostics::errorCount() const {
  return static_cast<size_t>(std::count_if(list_.begin(), list_.end(), [](const Diagnostic& d) {
    return d.severity == Severity::Error;
  }));
}

std::vector<Diagnostic> Diagnostics::sorted() const {
  std::vector<Diagnostic> out = list_;
  std::stable_sort(out.begin(), out.end(), [](const Diagnostic& a, const Diagnostic& b) {
    if (a.where.file != b.where.file) return a.where.file < b.where.file;
    if (a.where.line != b.where.line) return a.where.line < b.where.line;
    return a.where.col < b.where.col;
  });
  return out;
}

static std::string_view severityName(Severity s) {
  switch (s) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Note: return "note";
  }
  return "error";
}

namespace {
// One diagnostic is one line (plus its note lines): control characters that a graph string
// can carry into a message (a name "a\n#version 100") are written as escapes.
std::string oneLine(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    auto u = static_cast<unsigned char>(c);
    if (c == '\n') out += "\\n";
    else if (c == '\r') out += "\\r";
    else if (c == '\t') out += "\\t";
    else if (u < 0x20 || u == 0x7f) {
      static const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[u >> 4];
      out += hex[u & 15];
    } else out += c;
  }
  return out;
}
}  // namespace

std::string formatText(const Diagnostic& d) {
  std::string s;
  if (!d.where.file.empty()) {
    s += oneLine(d.where.file);
    if (d.where.line > 0) {
      s += ':' + std::to_string(d.where.line);
      if (d.where.col > 0) s += ':' + std::to_string(d.where.col);
    }
    s += ": ";
  }
  s += severityName(d.severity);
  s += ": [" + codeString(d.code) + "] " + oneLine(d.message);
  if (!d.node.empty() || !d.port.empty()) {
    s += " (";
    if (!d.node.empty()) s += "node '" + oneLine(d.node) + "'";
    if (!d.node.empty() && !d.port.empty()) s += ", ";
    s += oneLine(d.port);
    s += ")";
  }
  for (const auto& note : d.notes) s += "\n  note: " + oneLine(note);
  return s;
}

nlohmann::json toJson(const Diagnostic& d) {
  nlohmann::json j;
  j["code"] = codeString(d.code);
  j["severity"] = severityName(d.severity);
  j["message"] = d.message;
  j["file"] = d.where.file.str();
  j["line"] = d.where.line;
  j["column"] = d.where.col;
  if (!d.node.empty()) j["node"] = d.node;
  if (!d.port.empty()) j["port"] = d.port;
  if (!d.notes.empty()) j["notes"] = d.notes;
  return j;
}

}  // namespace wg
