#pragma once
#include <compare>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>

namespace wg {

// A file's name as every position in it carries it: a pointer to one interned copy of the
// string, so a position is a pointer and two ints, trivially copied and destroyed. (A shared
// pointer made every copy an atomic count and every position 24 bytes; a graph holds about
// ten positions per node, and the Program one per op.) Names are interned for the life of
// the process: a process reads a bounded set of files.
class FileName {
 public:
  FileName() = default;
  FileName(std::string_view name)  // NOLINT(google-explicit-constructor): a name is a name
      : name_(name.empty() ? nullptr : intern(name)) {}
  FileName(const std::string& name) : FileName(std::string_view(name)) {}  // NOLINT(google-explicit-constructor)
  FileName(const char* name) : FileName(std::string_view(name)) {}  // NOLINT(google-explicit-constructor)

  const std::string& str() const { return name_ ? *name_ : empty_(); }
  operator const std::string&() const { return str(); }  // NOLINT(google-explicit-constructor)
  bool empty() const { return !name_; }

  // Interned: equal names are the same pointer.
  friend bool operator==(const FileName& a, const FileName& b) { return a.name_ == b.name_; }
  friend std::strong_ordering operator<=>(const FileName& a, const FileName& b) { return a.str() <=> b.str(); }
  friend bool operator==(const FileName& a, std::string_view b) { return a.str() == b; }
  friend bool operator==(const FileName& a, const std::string& b) { return a.str() == b; }
  friend bool operator==(const FileName& a, const char* b) { return a.str() == b; }
  friend std::ostream& operator<<(std::ostream& os, const FileName& f) { return os << f.str(); }

 private:
  static const std::string* intern(std::string_view name);  // thread-safe; never freed
  static const std::string& empty_() {
    static const std::string none;
    return none;
  }
  const std::string* name_ = nullptr;
};

// Where something came from in a graph file: 1-based line and column, 0 when unknown.
struct SourceRef {
  FileName file;
  int line = 0;
  int col = 0;

  friend bool operator==(const SourceRef&, const SourceRef&) = default;
};

}  // namespace wg
