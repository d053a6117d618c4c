#include "nodes/glsl_library.h"

#include <algorithm>
#include <stdexcept>

#include "core/glsl_operation_count.h"
#include "nodes/glsl_library_cost.h"

namespace wg {
namespace {

bool identChar(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

// Top-level items of one file: text from the comment block above an item to its closing
// '}' (function) or ';' (constant) at brace depth 0.
std::vector<GlslItem> splitFile(const std::string& file, std::string_view text) {
  std::vector<GlslItem> items;
  size_t i = 0, n = text.size();
  size_t itemStart = std::string_view::npos;  // first line of the pending comment/definition
  int depth = 0;
  bool inDefinition = false;
  while (i < n) {
    if (text.compare(i, 2, "//") == 0) {
      size_t eol = text.find('\n', i);
      if (itemStart == std::string_view::npos) itemStart = i;
      i = eol == std::string_view::npos ? n : eol + 1;
      continue;
    }
    if (text.compare(i, 2, "/*") == 0) {
      size_t end = text.find("*/", i + 2);
      if (end == std::string_view::npos) throw std::logic_error(file + ".glsl: unterminated comment");
      if (itemStart == std::string_view::npos) itemStart = i;
      i = end + 2;
      continue;
    }
    char c = text[i];
    if (c == '\n' && !inDefinition && depth == 0) {
      // A blank line ends a comment block that belongs to no definition (file header).
      size_t next = i + 1;
      if (next < n && text[next] == '\n') itemStart = std::string_view::npos;
      ++i;
      continue;
    }
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
      ++i;
      continue;
    }
    if (c == '#') throw std::logic_error(file + ".glsl: preprocessor lines are not allowed in the library");
    if (!inDefinition) {
      inDefinition = true;
      if (itemStart == std::string_view::npos) itemStart = i;
    }
    if (c == '{') ++depth;
    if (c == '}') {
      if (--depth < 0) throw std::logic_error(file + ".glsl: unbalanced '}'");
    }
    bool ends = (c == '}' && depth == 0) || (c == ';' && depth == 0);
    ++i;
    if (!ends) continue;
    // A function ends at its body's '}'; a ';' right after (struct) belongs to it.
    std::string item(text.substr(itemStart, i - itemStart));
    // Name: for a function, the identifier before the first '('; for a constant, before '='.
    size_t codeStart = 0;
    while (true) {  // skip the leading comment lines
      size_t p = item.find_first_not_of(" \t\r\n", codeStart);
      if (p != std::string::npos && item.compare(p, 2, "//") == 0) {
        codeStart = item.find('\n', p) + 1;
        continue;
      }
      codeStart = p;
      break;
    }
    std::string code = item.substr(codeStart);
    size_t cut = code.find_first_of("(=");
    if (cut == std::string::npos) throw std::logic_error(file + ".glsl: cannot name the item: " + code.substr(0, 60));
    size_t e = cut;
    while (e > 0 && (code[e - 1] == ' ' || code[e - 1] == '\t')) --e;
    size_t b = e;
    while (b > 0 && identChar(code[b - 1])) --b;
    std::string name = code.substr(b, e - b);
    if (name.rfind("wg_", 0) != 0 && name.rfind("WG_", 0) != 0)
      throw std::logic_error(file + ".glsl: library item '" + name + "' must be named wg_* or WG_*");
    items.push_back({name, file, item, {}});
    itemStart = std::string_view::npos;
    inDefinition = false;
  }
  if (depth != 0 || inDefinition) throw std::logic_error(file + ".glsl: unterminated definition");
  return items;
}

std::string withoutLineComments(const std::string& text) {
  std::string out;
  size_t i = 0;
  while (i < text.size()) {
    size_t c = text.find("//", i);
    if (c == std::string::npos) {
      out += text.substr(i);
      break;
    }
    out += text.substr(i, c - i);
    size_t eol = text.find('\n', c);
    i = eol == std::string::npos ? text.size() : eol;
  }
  return out;
}

}  // namespace

std::vector<std::string> libraryIdentifiers(std::string_view code) {
  std::vector<std::string> out;
  size_t i = 0, n = code.size();
  while (i < n) {
    if (!identChar(code[i])) {
      ++i;
      continue;
    }
    size_t b = i;
    while (i < n && identChar(code[i])) ++i;
    std::string_view word = code.substr(b, i - b);
    if ((word.rfind("wg_", 0) == 0 || word.rfind("WG_", 0) == 0) &&
        std::find(out.begin(), out.end(), word) == out.end())
      out.emplace_back(word);
  }
  return out;
}

GlslLibrary::GlslLibrary(const std::vector<GlslSourceFile>& files) {
  std::vector<GlslSourceFile> sorted = files;
  std::sort(sorted.begin(), sorted.end(),
            [](const GlslSourceFile& a, const GlslSourceFile& b) { return std::string_view(a.name) < b.name; });
  for (const auto& f : sorted)
    for (auto& item : splitFile(f.name, f.text)) items_.push_back(std::move(item));
  std::set<std::string> names;
  for (const auto& it : items_)
    if (!names.insert(it.name).second)
      throw std::logic_error(it.file + ".glsl: '" + it.name +
                             "' is defined twice; the library names one variant per type (wg_x_vec3) instead of overloading");
  for (auto& it : items_) {
    // Uses are scanned in the code only, not in the comments.
    for (const auto& id : libraryIdentifiers(withoutLineComments(it.text)))
      if (id != it.name && names.count(id)) it.uses.push_back(id);
  }
  // Indexed once: itemsNamed runs for every stage of every compile.
  for (size_t i = 0; i < items_.size(); ++i) index_.emplace(items_[i].name, i);
  useIndex_.resize(items_.size());
  for (size_t i = 0; i < items_.size(); ++i)
    for (const auto& u : items_[i].uses) useIndex_[i].push_back(index_.at(u));
}

const GlslLibrary& GlslLibrary::builtin() {
  static const GlslLibrary library(embeddedGlslFiles());
  // Core's operation counts price calls of its functions by their bodies.
  static const bool costsInstalled = (setLibraryCallCost(&builtinLibraryCallCost), true);
  (void)costsInstalled;
  return library;
}

bool GlslLibrary::has(std::string_view name) const { return index_.count(std::string(name)) > 0; }

std::vector<const GlslItem*> GlslLibrary::itemsNamed(const std::vector<std::string>& names) const {
  // Reachable set, then emit in library order whenever all uses are already emitted
  // (the library has no recursion: GLSL forbids it). Names are unique (the constructor
  // refuses a second definition), so an item is emitted once it is done.
  std::vector<char> wanted(items_.size(), 0);
  std::vector<size_t> work;
  for (const auto& name : names) {
    auto it = index_.find(name);
    if (it != index_.end() && !wanted[it->second]) {
      wanted[it->second] = 1;
      work.push_back(it->second);
    }
  }
  while (!work.empty()) {
    size_t i = work.back();
    work.pop_back();
    for (size_t u : useIndex_[i])
      if (!wanted[u]) {
        wanted[u] = 1;
        work.push_back(u);
      }
  }
  std::vector<const GlslItem*> out;
  std::vector<char> done(items_.size(), 0);
  bool progress = true;
  while (progress) {
    progress = false;
    for (size_t i = 0; i < items_.size(); ++i) {
      if (!wanted[i] || done[i]) continue;
      bool ready = std::all_of(useIndex_[i].begin(), useIndex_[i].end(), [&](size_t u) { return done[u] != 0; });
      if (!ready) continue;
      out.push_back(&items_[i]);
      done[i] = 1;
      progress = true;
      break;  // restart so the earliest ready item always goes next
    }
  }
  for (size_t i = 0; i < items_.size(); ++i)
    if (wanted[i] && !done[i]) throw std::logic_error("GLSL library: circular use involving " + items_[i].name);
  return out;
}

}  // namespace wg
