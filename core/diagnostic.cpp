#include "core/diagnostic.h"

#include "core/shown_text.h"

#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>

namespace wg {

const std::vector<DiagCodeInfo>& diagnosticCatalogue() {
  static const std::vector<DiagCodeInfo> catalogue = {
#define WG_DIAG(name, number, summary, example) {DiagCode::name, #name, summary, example},
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

Diagnostic& Diagnostics::keep(Diagnostic d) {
  size_t& count = perFile_[d.where.file];
  if (count >= kMaxPerFile) {
    LeftOut& left = leftOut_[d.where.file];
    ++(d.severity == Severity::Error ? left.errors : left.others);
    scratch_ = std::move(d);
    return scratch_;
  }
  ++count;
  list_.push_back(std::move(d));
  return list_.back();
}

Diagnostic& Diagnostics::error(DiagCode code, SourceRef where, std::string message, std::string node,
                               std::string port) {
  return keep({code, Severity::Error, std::move(message), std::move(where), std::move(node), std::move(port), {}});
}

Diagnostic& Diagnostics::warning(DiagCode code, SourceRef where, std::string message,
                                 std::string node, std::string port) {
  return keep({code, Severity::Warning, std::move(message), std::move(where), std::move(node), std::move(port), {}});
}

void Diagnostics::add(Diagnostic d) { keep(std::move(d)); }

void Diagnostics::append(const Diagnostics& other) {
  for (const auto& d : other.list_) keep(d);
  for (const auto& [file, left] : other.leftOut_) {
    leftOut_[file].errors += left.errors;
    leftOut_[file].others += left.others;
  }
  for (const auto& [file, text] : other.sources_) sources_.emplace(file, text);
}

void Diagnostics::addLocatedNoteFrom(size_t first, const LocatedNote& note) {
  for (size_t i = first; i < list_.size(); ++i) list_[i].locatedNotes.push_back(note);
}

bool Diagnostics::hasErrors() const { return errorCount() > 0; }

size_t Diagnostics::errorCount() const {
  size_t n = static_cast<size_t>(std::count_if(list_.begin(), list_.end(), [](const Diagnostic& d) {
    return d.severity == Severity::Error;
  }));
  for (const auto& [file, left] : leftOut_) n += left.errors;
  return n;
}

std::vector<Diagnostic> Diagnostics::sorted() const {
  std::vector<Diagnostic> out = list_;
  std::stable_sort(out.begin(), out.end(), [](const Diagnostic& a, const Diagnostic& b) {
    if (a.where.file != b.where.file) return a.where.file < b.where.file;
    if (a.where.line != b.where.line) return a.where.line < b.where.line;
    return a.where.col < b.where.col;
  });
  for (const auto& [file, left] : leftOut_) {
    size_t total = left.errors + left.others;
    out.push_back({DiagCode::TooManyDiagnostics, Severity::Note,
                   std::to_string(total) + " more diagnostic" + (total == 1 ? "" : "s") + " (" +
                       std::to_string(left.errors) + " error" + (left.errors == 1 ? "" : "s") +
                       ") not shown: at most " + std::to_string(kMaxPerFile) + " are reported per file",
                   SourceRef{file, 0, 0}, {}, {}, {}});
  }
  return out;
}

void Diagnostics::keepSource(const std::string& file, std::shared_ptr<const std::string> text) {
  sources_[file] = std::move(text);
}

void Diagnostics::keepSourcesOf(const Diagnostics& other) {
  for (const auto& [file, text] : other.sources_) sources_.emplace(file, text);
}

const std::string* Diagnostics::source(const std::string& file) const {
  auto it = sources_.find(file);
  return it == sources_.end() ? nullptr : it->second.get();
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
// can carry into a message (a name "a\n#version 100"), and bytes of a file name that are not
// UTF-8, are written as escapes (core/shown_text.h).
std::string oneLine(const std::string& text) { return escapedForTerminal(text); }
}  // namespace

namespace {
// "file:line:col: " (as much of it as is known), or "".
std::string locationPrefix(const SourceRef& where) {
  if (where.file.empty()) return "";
  std::string s = oneLine(where.file);
  if (where.line > 0) {
    s += ':' + std::to_string(where.line);
    if (where.col > 0) s += ':' + std::to_string(where.col);
  }
  return s + ": ";
}
}  // namespace

std::string formatText(const Diagnostic& d) {
  std::string s = locationPrefix(d.where);
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
  for (const auto& note : d.locatedNotes) s += "\n" + locationPrefix(note.where) + "note: " + oneLine(note.message);
  return s;
}

nlohmann::json toJson(const Diagnostic& d) {
  // Every string as valid UTF-8 (core/shown_text.h): a file name need not be, and JSON
  // cannot hold it otherwise.
  nlohmann::json j;
  j["code"] = codeString(d.code);
  j["severity"] = severityName(d.severity);
  j["message"] = validUtf8(d.message);
  j["file"] = validUtf8(d.where.file.str());
  j["line"] = d.where.line;
  j["column"] = d.where.col;
  if (!d.node.empty()) j["node"] = validUtf8(d.node);
  if (!d.port.empty()) j["port"] = validUtf8(d.port);
  if (!d.notes.empty()) {
    nlohmann::json notes = nlohmann::json::array();
    for (const auto& n : d.notes) notes.push_back(validUtf8(n));
    j["notes"] = std::move(notes);
  }
  if (!d.locatedNotes.empty()) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& n : d.locatedNotes)
      list.push_back({{"file", validUtf8(n.where.file.str())}, {"line", n.where.line}, {"column", n.where.col},
                      {"message", validUtf8(n.message)}});
    j["located_notes"] = std::move(list);
  }
  return j;
}

}  // namespace wg
