#pragma once
// Errors the runtime reports. Each is one line that names what failed; the kind tells the
// CLI which exit code to use (environment and I/O problems 2, shader and manifest 1).
#include <stdexcept>
#include <string>

namespace wg::rt {

class RuntimeError : public std::runtime_error {
 public:
  enum class Kind {
    Environment,  // no EGL, no display, no context of the asked API: exit 2
    Io,           // an image could not be written: exit 2
    Driver,       // the driver rejected a shader glslang accepted, or a GL call failed: exit 1
    Manifest,     // the manifest asks for something the runtime cannot do: exit 1
    Budget,       // the size asked for would pass the memory budget (memory_budget.h): exit 2
  };
  RuntimeError(Kind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  Kind kind() const { return kind_; }
  int exitCode() const { return kind_ == Kind::Environment || kind_ == Kind::Io || kind_ == Kind::Budget ? 2 : 1; }

 private:
  Kind kind_;
};

// A texture the graph names that the runtime cannot load (a PNG whose header passed the
// compile-time check but whose data does not decode, a file gone since): a fault of the
// graph's input. Callers that hold the graph report it as WG030 at the option naming the
// texture (codegen/texture_files.h, reportUnusableTexture); exit 1.
class TextureLoadError : public RuntimeError {
 public:
  TextureLoadError(const std::string& message, std::string source, std::string why)
      : RuntimeError(Kind::Manifest, message), source_(std::move(source)), why_(std::move(why)) {}
  const std::string& source() const { return source_; }  // as the graph names it
  const std::string& why() const { return why_; }

 private:
  std::string source_, why_;
};

// The manifest asks for something the runtime cannot do (the GL and Vulkan renderers).
[[noreturn]] inline void manifestError(const std::string& message) {
  throw RuntimeError(RuntimeError::Kind::Manifest, message);
}

}  // namespace wg::rt
