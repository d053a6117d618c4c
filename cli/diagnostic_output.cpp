#include <algorithm>
#include <cctype>
#include <iostream>
#include <map>
#include <sstream>
#include <string_view>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "core/shown_text.h"
#include "core/text_lines.h"

namespace wg::cli {
namespace {

// A path as a SARIF artifact URI: relative paths stay relative (code-scanning tools resolve
// them against the repository root), absolute ones become file:// URIs; everything but
// RFC 3986 unreserved characters and '/' is percent-encoded.
std::string pathToUri(const std::string& path) {
  static const char* hex = "0123456789ABCDEF";
  std::string out = !path.empty() && path[0] == '/' ? "file://" : "";
  std::string p = path;
  if (p.rfind("./", 0) == 0) p = p.substr(2);
  for (unsigned char c : p) {
    if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') {
      out += static_cast<char>(c);
    } else {
      out += '%';
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  return out;
}

// Diagnostics count columns in bytes; SARIF's default columnKind is UTF-16 code units.
// Converts from the text the file was parsed from (the one snapshot that was read: the file
// is never opened again, it may be a FIFO or have changed since); keeps the byte column
// when there is no such text.
class ColumnConverter {
 public:
  explicit ColumnConverter(const Diagnostics& diags) : diags_(diags) {}

  int utf16Column(const std::string& file, int line, int byteCol) {
    if (line <= 0 || byteCol <= 1) return byteCol;
    const std::vector<std::string_view>& lines = linesOf(file);
    if (static_cast<size_t>(line) > lines.size()) return byteCol;
    std::string_view text = lines[static_cast<size_t>(line - 1)];
    int units = 0;
    size_t i = 0;
    size_t end = std::min(text.size(), static_cast<size_t>(byteCol - 1));
    while (i < end) {
      unsigned char c = static_cast<unsigned char>(text[i]);
      size_t len = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 1;
      units += len == 4 ? 2 : 1;
      i += len;
    }
    if (end < static_cast<size_t>(byteCol - 1)) units += static_cast<int>(byteCol - 1 - end);  // past the end
    return units + 1;
  }

 private:
  const std::vector<std::string_view>& linesOf(const std::string& file) {
    auto it = cache_.find(file);
    if (it != cache_.end()) return it->second;
    const std::string* text = diags_.source(file);
    return cache_.emplace(file, text ? splitLines(*text) : std::vector<std::string_view>{}).first->second;
  }
  const Diagnostics& diags_;
  std::map<std::string, std::vector<std::string_view>> cache_;
};

const char* sarifLevel(Severity s) {
  switch (s) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Note: return "note";
  }
  return "error";
}

// One SARIF 2.1.0 log: a run whose driver lists every code of the catalogue as a rule.
nlohmann::json sarifLog(const Diagnostics& diags) {
  nlohmann::json rules = nlohmann::json::array();
  std::map<DiagCode, size_t> ruleIndex;
  for (const auto& info : diagnosticCatalogue()) {
    ruleIndex[info.code] = rules.size();
    std::string summary(info.summary);
    rules.push_back({{"id", codeString(info.code)},
                     {"name", std::string(info.enumerator)},
                     {"shortDescription", {{"text", summary}}},
                     {"fullDescription", {{"text", summary}}},
                     {"help", {{"text", "See the error code table in docs/graph-format.md."}}},
                     {"defaultConfiguration", {{"level", "error"}}}});
  }
  ColumnConverter columns(diags);
  nlohmann::json results = nlohmann::json::array();
  for (const auto& d : diags.sorted()) {
    std::string text = d.message;
    if (!d.node.empty() || !d.port.empty()) {
      text += " (";
      if (!d.node.empty()) text += "node '" + d.node + "'";
      if (!d.node.empty() && !d.port.empty()) text += ", ";
      text += d.port + ")";
    }
    for (const auto& note : d.notes) text += "\nnote: " + note;
    for (const auto& note : d.locatedNotes) text += "\nnote: " + note.message;
    nlohmann::json r{{"ruleId", codeString(d.code)},
                     {"level", sarifLevel(d.severity)},
                     {"message", {{"text", validUtf8(text)}}}};
    auto idx = ruleIndex.find(d.code);
    if (idx != ruleIndex.end()) r["ruleIndex"] = idx->second;
    if (!d.where.file.empty()) {
      nlohmann::json phys{{"artifactLocation", {{"uri", pathToUri(d.where.file)}}}};
      if (d.where.line > 0) {
        nlohmann::json region{{"startLine", d.where.line}};
        if (d.where.col > 0) region["startColumn"] = columns.utf16Column(d.where.file, d.where.line, d.where.col);
        phys["region"] = region;
      }
      nlohmann::json loc{{"physicalLocation", phys}};
      if (!d.node.empty())
        loc["logicalLocations"] = nlohmann::json::array({{{"name", validUtf8(d.node)}, {"kind", "object"}}});
      r["locations"] = nlohmann::json::array({loc});
    }
    // The subgraph instances it lies in, innermost first.
    nlohmann::json related = nlohmann::json::array();
    for (const auto& note : d.locatedNotes) {
      nlohmann::json phys{{"artifactLocation", {{"uri", pathToUri(note.where.file)}}}};
      if (note.where.line > 0) {
        nlohmann::json region{{"startLine", note.where.line}};
        if (note.where.col > 0)
          region["startColumn"] = columns.utf16Column(note.where.file, note.where.line, note.where.col);
        phys["region"] = region;
      }
      related.push_back({{"id", related.size()}, {"physicalLocation", phys}, {"message", {{"text", validUtf8(note.message)}}}});
    }
    if (!related.empty()) r["relatedLocations"] = related;
    nlohmann::json props = nlohmann::json::object();
    if (!d.node.empty()) props["node"] = validUtf8(d.node);
    if (!d.port.empty()) props["port"] = validUtf8(d.port);
    if (!props.empty()) r["properties"] = props;
    results.push_back(r);
  }
  nlohmann::json driver{{"name", "watergraph"},
                        {"version", "0.1.0"},
                        {"semanticVersion", "0.1.0"},
                        {"rules", rules}};
  return {{"$schema", "https://json.schemastore.org/sarif-2.1.0.json"},
          {"version", "2.1.0"},
          {"runs", nlohmann::json::array({{{"tool", {{"driver", driver}}},
                                           {"columnKind", "utf16CodeUnits"},
                                           {"results", results}}})}};
}

}  // namespace

void printDiagnostics(const Diagnostics& diags, const GlobalOptions& global) {
  if (global.diagnosticsFormat == "sarif") {
    // Always one complete log, even with no results: CI uploads the file either way.
    std::cout << sarifLog(diags).dump(2) << "\n";
    return;
  }
  if (diags.empty()) return;
  if (global.diagnosticsFormat == "json") {
    nlohmann::json all = nlohmann::json::array();
    for (const auto& d : diags.sorted()) all.push_back(toJson(d));
    std::cout << nlohmann::json{{"diagnostics", all}}.dump(2) << "\n";
    return;
  }
  for (const auto& d : diags.sorted()) std::cerr << formatText(d) << "\n";
}

int exitCodeFor(const Diagnostics& diags) {
  bool graphError = false;
  for (const auto& d : diags.all()) {
    if (d.severity != Severity::Error) continue;
    // WG05x are the files and the command line (an unreadable file, --preset naming no
    // preset): exit 2, as for other usage and I/O errors.
    if (d.code != DiagCode::FileRead && d.code != DiagCode::FileWrite && d.code != DiagCode::UnknownPreset)
      graphError = true;
  }
  return graphError ? kExitGraphError : kExitUsageOrIo;
}

}  // namespace wg::cli
