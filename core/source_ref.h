#pragma once
#include <compare>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>

namespace wg {

// A file's name as every position in it carries it: one string shared by all of them, so
// copying a position costs a reference count, not a string (a graph holds about ten
// positions per node, and a path longer than the small-string buffer made each a heap copy).
class FileName {
 public:
  FileName() = default;
  FileName(std::string name)  // NOLINT(google-explicit-constructor): a name is a name
      : name_(name.empty() ? nullptr : std::make_shared<const std::string>(std::move(name))) {}
  FileName(const char* name) : FileName(std::string(name)) {}  // NOLINT(google-explicit-constructor)

  const std::string& str() const { return name_ ? *name_ : empty_(); }
  operator const std::string&() const { return str(); }  // NOLINT(google-explicit-constructor)
  bool empty() const { return !name_; }

  friend bool operator==(const FileName& a, const FileName& b) { return a.name_ == b.name_ || a.str() == b.str(); }
  friend std::strong_ordering operator<=>(const FileName& a, const FileName& b) { return a.str() <=> b.str(); }
  friend bool operator==(const FileName& a, std::string_view b) { return a.str() == b; }
  friend bool operator==(const FileName& a, const std::string& b) { return a.str() == b; }
  friend bool operator==(const FileName& a, const char* b) { return a.str() == b; }
  friend std::ostream& operator<<(std::ostream& os, const FileName& f) { return os << f.str(); }

 private:
  static const std::string& empty_() {
    static const std::string none;
    return none;
  }
  std::shared_ptr<const std::string> name_;
};

// Where something came from in a graph file: 1-based line and column, 0 when unknown.
struct SourceRef {
  FileName file;
  int line = 0;
  int col = 0;

  friend bool operator==(const SourceRef&, const SourceRef&) = default;
};

}  // namespace wg
