#pragma once
// A helper program kept running beside the compiler and spoken to in JSON lines: one request
// line on its standard input, one reply line on its standard output. The WebGPU probe keeps
// one (clients/webgpu/probe_server.mjs: Node.js driving headless Chromium) for all its runs,
// because starting Chromium takes seconds and a node probe or the hard-case suite runs many
// shaders. Its standard error goes to a temporary file, quoted when it fails.
#include <string>
#include <sys/types.h>
#include <vector>

#include <nlohmann/json.hpp>

namespace wg::accuracy {

class JsonLineProcess {
 public:
  // Starts argv[0] (a path) with `argv`. Throws std::runtime_error when it cannot be started.
  explicit JsonLineProcess(const std::vector<std::string>& argv);
  // Closes its standard input (the helper then ends) and waits for it, killing it (by its
  // id) if it has not ended within a few seconds.
  ~JsonLineProcess();
  JsonLineProcess(const JsonLineProcess&) = delete;
  JsonLineProcess& operator=(const JsonLineProcess&) = delete;

  void send(const nlohmann::json& request);
  // The next line that is a JSON object (other lines are skipped). Throws std::runtime_error
  // when the helper ends or stays silent for `timeoutSeconds`; the message quotes the end of
  // its standard error.
  nlohmann::json receive(int timeoutSeconds);

 private:
  std::string stderrTail() const;
  [[noreturn]] void fail(const std::string& why);

  pid_t pid_ = -1;
  int socket_ = -1;     // the parent's end: the helper's stdin and stdout
  int stderrFile_ = -1;  // an unlinked temporary file
  std::string pending_;  // read but not yet returned
};

}  // namespace wg::accuracy
