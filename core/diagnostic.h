#pragma once
// Diagnostics with stable codes from one catalogue (core/diagnostic_codes.def), printed
// as `file:line:col: error: [WG029] message (node 'n', input 'p')` or as JSON.
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/source_ref.h"

namespace wg {

enum class DiagCode : int {
#define WG_DIAG(name, number, summary, example) name = number,
#include "core/diagnostic_codes.def"
#undef WG_DIAG
};

struct DiagCodeInfo {
  DiagCode code;
  std::string_view enumerator;
  std::string_view summary;
  std::string_view example;  // one line of what causes it (docs/diagnostics.md)
};
const std::vector<DiagCodeInfo>& diagnosticCatalogue();
std::string codeString(DiagCode code);  // "WG029"

enum class Severity { Error, Warning, Note };

// A note that points somewhere else: each instance of a subgraph that a diagnostic inside
// it lies in, innermost first (`lake.json:12:5: note: in instance 'foam' of 'lib/foam.json'`).
struct LocatedNote {
  SourceRef where;
  std::string message;
  std::string node;  // the instance's id in the graph of `where` ("" for a note naming no node)
};

struct Diagnostic {
  DiagCode code{};
  Severity severity = Severity::Error;
  std::string message;
  SourceRef where;
  std::string node;  // node id, when one is involved
  std::string port;  // "input 'normal'", "option 'model'", "output 'color'"
  std::vector<std::string> notes;
  std::vector<LocatedNote> locatedNotes;
};

// A hostile file can hold a million faults; each file keeps its first kMaxPerFile
// diagnostics and counts the rest, which sorted() (what every output format prints) sums
// up in one WG036 note per file.
class Diagnostics {
 public:
  static constexpr size_t kMaxPerFile = 1000;

  // Past the cap, the returned Diagnostic is a scratch one that is not kept.
  Diagnostic& error(DiagCode code, SourceRef where, std::string message, std::string node = {},
                    std::string port = {});
  Diagnostic& warning(DiagCode code, SourceRef where, std::string message, std::string node = {},
                      std::string port = {});
  void add(Diagnostic d);
  void append(const Diagnostics& other);
  bool hasErrors() const;
  // Counts the errors left out past the cap too.
  size_t errorCount() const;
  // The diagnostics kept (at most kMaxPerFile per file), without the WG036 notes.
  const std::vector<Diagnostic>& all() const { return list_; }
  bool empty() const { return list_.empty(); }
  // Adds `note` to every diagnostic kept from the `first`-th on (an index into all()):
  // those reported while resolving one subgraph instance get the instance's note.
  void addLocatedNoteFrom(size_t first, const LocatedNote& note);
  // Stable order for printing: by file, line, column, then insertion; then, for each file
  // over the cap, the note saying how many were left out.
  std::vector<Diagnostic> sorted() const;

  // The text a graph file was parsed from, kept so that output formats that need the
  // file's lines (SARIF's UTF-16 columns) use the one snapshot that was read instead of
  // opening the file again (it may be a FIFO, or have changed). nullptr when not kept.
  void keepSource(const std::string& file, std::shared_ptr<const std::string> text);
  const std::string* source(const std::string& file) const;
  // Keeps every source text `other` keeps: a scratch Diagnostics for a trial build reports
  // columns inside strings (escapes counted) as the main one would.
  void keepSourcesOf(const Diagnostics& other);

 private:
  Diagnostic& keep(Diagnostic d);
  struct LeftOut {
    size_t errors = 0, others = 0;
  };
  std::vector<Diagnostic> list_;
  std::map<std::string, size_t> perFile_;
  std::map<std::string, LeftOut> leftOut_;
  std::map<std::string, std::shared_ptr<const std::string>> sources_;
  Diagnostic scratch_;
};

std::string formatText(const Diagnostic& d);
nlohmann::json toJson(const Diagnostic& d);

}  // namespace wg
