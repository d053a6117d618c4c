#include "core/source_ref.h"

#include <mutex>
#include <unordered_set>

namespace wg {

const std::string* FileName::intern(std::string_view name) {
  // Node-based: an element's address never changes. Allocated once and never destroyed, so
  // positions held by other static objects stay valid during exit.
  static std::mutex* mutex = new std::mutex;
  static auto* names = new std::unordered_set<std::string>;
  std::lock_guard<std::mutex> lock(*mutex);
  return &*names->emplace(name).first;
}

}  // namespace wg
