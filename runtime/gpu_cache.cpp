#include "runtime/gpu_cache.h"

#include <algorithm>

namespace wg::rt {
namespace {

// The whole text, not a hash: two different programs can never share an entry.
std::string programKey(const std::vector<ShaderSource>& sources) {
  std::string key;
  for (const auto& s : sources) {
    key += std::to_string(s.stage);
    key += '\0';
    key += s.name;
    key += '\0';
    key += std::to_string(s.text.size());
    key += '\0';
    key += s.text;
  }
  return key;
}

}  // namespace

template <class T>
std::shared_ptr<const T> GpuCache::lookUp(std::vector<Entry<T>>& entries, const std::string& key) {
  auto it = std::find_if(entries.begin(), entries.end(), [&](const Entry<T>& e) { return e.key == key; });
  if (it == entries.end()) return nullptr;
  std::rotate(it, it + 1, entries.end());  // now the most recently used
  return entries.back().object;
}

template <class T>
void GpuCache::insert(std::vector<Entry<T>>& entries, std::string key, std::shared_ptr<const T> object) {
  // Drop the oldest entries nobody else holds while more than keepUnused_ of them remain.
  size_t unused = static_cast<size_t>(
      std::count_if(entries.begin(), entries.end(), [](const Entry<T>& e) { return e.object.use_count() == 1; }));
  for (auto it = entries.begin(); unused > keepUnused_ && it != entries.end();) {
    if (it->object.use_count() == 1) {
      it = entries.erase(it);
      --unused;
    } else {
      ++it;
    }
  }
  entries.push_back({std::move(key), std::move(object)});
}

std::shared_ptr<const Program> GpuCache::program(const std::vector<ShaderSource>& sources, const std::string& what) {
  std::string key = programKey(sources);
  if (auto hit = lookUp(programs_, key)) {
    ++counts_.programHits;
    return hit;
  }
  auto linked = std::make_shared<const Program>(linkProgram(sources, what));
  ++counts_.programLinks;
  insert(programs_, std::move(key), linked);
  return linked;
}

std::shared_ptr<const Texture> GpuCache::texture(const std::string& key, const std::function<Texture()>& make) {
  if (auto hit = lookUp(textures_, key)) {
    ++counts_.textureHits;
    return hit;
  }
  auto made = std::make_shared<const Texture>(make());
  ++counts_.textureUploads;
  insert(textures_, key, made);
  return made;
}

GpuCache::Stats GpuCache::stats() const {
  Stats s = counts_;
  s.programs = programs_.size();
  s.textures = textures_.size();
  return s;
}

}  // namespace wg::rt
