#pragma once
// GL objects that outlive one Renderer in the same context: linked programs keyed by their
// shader texts, and node textures keyed by where they come from.
//
// Why: an editor builds a new Renderer on every edit. Most edits (a parameter default, a
// colour) leave every shader text unchanged, and the scene's sky and opaque programs never
// change. Mesa compiles a program's machine code at its first draw and keeps it with the
// program object, so linking the same text again costs that JIT again: on llvmpipe 0.3 to
// 0.7 s per edit. Handing the same program object to the next Renderer costs nothing.
//
// The context the objects belong to must be current whenever the cache is used or
// destroyed. Renderers hold shared references, so an entry stays alive while any Renderer
// uses it. Each time an entry is made, the oldest of the others that nobody else holds are
// dropped until at most `keepUnused` of them remain.
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "runtime/gl_resources.h"

namespace wg::rt {

class GpuCache {
 public:
  explicit GpuCache(size_t keepUnused = 8) : keepUnused_(keepUnused) {}
  GpuCache(const GpuCache&) = delete;
  GpuCache& operator=(const GpuCache&) = delete;

  // The program linked from exactly these sources (stages, names and texts), linked now
  // through linkProgram when the cache has none; its errors propagate unchanged.
  std::shared_ptr<const Program> program(const std::vector<ShaderSource>& sources, const std::string& what);
  // The texture stored under `key`, made by `make` when the cache has none.
  std::shared_ptr<const Texture> texture(const std::string& key, const std::function<Texture()>& make);

  struct Stats {
    size_t programHits = 0, programLinks = 0, textureHits = 0, textureUploads = 0;
    size_t programs = 0, textures = 0;  // entries held now
  };
  Stats stats() const;

 private:
  template <class T>
  struct Entry {
    std::string key;
    std::shared_ptr<const T> object;
  };
  // Most recently used last; a linear search: an editor holds a handful of entries.
  std::vector<Entry<Program>> programs_;
  std::vector<Entry<Texture>> textures_;
  size_t keepUnused_;
  Stats counts_;

  template <class T>
  static std::shared_ptr<const T> lookUp(std::vector<Entry<T>>& entries, const std::string& key);
  template <class T>
  void insert(std::vector<Entry<T>>& entries, std::string key, std::shared_ptr<const T> object);
};

}  // namespace wg::rt
