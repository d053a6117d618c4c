#pragma once
// The GLSL function library (nodes/glsl/*.glsl, embedded at build time) split into its
// top-level items — functions and constants, all named wg_* / WG_* — so the emitter can
// pull in exactly the items a shader calls, dependencies first, in a stable order.
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace wg {

struct GlslSourceFile {
  const char* name;  // file name without .glsl
  const char* text;
};
const std::vector<GlslSourceFile>& embeddedGlslFiles();  // generated

struct GlslItem {
  std::string name;   // wg_fresnel_schlick (unique: variants per type are named wg_x_vec3, not overloaded)
  std::string file;   // "fresnel"
  std::string text;   // the definition, with the comment lines right above it
  std::vector<std::string> uses;  // other library names it refers to
};

class GlslLibrary {
 public:
  // Parses files; throws std::logic_error naming the file on a malformed one.
  explicit GlslLibrary(const std::vector<GlslSourceFile>& files);
  static const GlslLibrary& builtin();  // the embedded library

  bool has(std::string_view name) const;
  // The items named in `names` (names the library lacks are no items of it: GLSL built-in
  // functions), plus everything they use, ordered so each item follows what it uses; ties
  // keep library order (file name, position). The names come from the calls the plan
  // recorded (EmitContext::call), never from a search of generated text.
  std::vector<const GlslItem*> itemsNamed(const std::vector<std::string>& names) const;
  const std::vector<GlslItem>& items() const { return items_; }

 private:
  std::vector<GlslItem> items_;  // library order
  std::unordered_map<std::string, size_t> index_;  // name -> its item (names are unique)
  std::vector<std::vector<size_t>> useIndex_;      // per item: the items it uses
};

// Every wg_* / WG_* identifier in `code`, in order of first appearance: what a library
// item's own (hand-written) text uses.
std::vector<std::string> libraryIdentifiers(std::string_view code);

}  // namespace wg
