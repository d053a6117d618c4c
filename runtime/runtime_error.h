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
  };
  RuntimeError(Kind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  Kind kind() const { return kind_; }
  int exitCode() const { return kind_ == Kind::Environment || kind_ == Kind::Io ? 2 : 1; }

 private:
  Kind kind_;
};

}  // namespace wg::rt
