#pragma once
// A helper program started beside the compiler and spoken to in JSON lines on its standard
// input and output, the one way watergraph starts a program of its own (no shell, no quoting):
// - kept open, one request line, one reply line: the WebGPU executor of probe and check
//   (clients/webgpu/executor_server.mjs: Node.js driving headless Chromium), because starting
//   Chromium takes seconds and a probe or check sends many jobs;
// - run to its end over arguments, reading every line it writes: validate's naga and Tint
//   checks (clients/webgpu/naga_check.mjs, tint_check.mjs; cli/wgsl_checks.cpp).
// Its standard error goes to an unlinked temporary file, quoted when it fails. It lives in core,
// the lowest layer, so that cli (validate, without the runtime) and accuracy both use it.
#include <string>
#include <sys/types.h>
#include <vector>

#include <nlohmann/json.hpp>

namespace wg {

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

  // Closes its standard input, reads every JSON object line it writes until it closes its
  // output, and waits for it; returns the lines, and its exit status in `exitStatus` (-1 when
  // it did not exit normally). Throws std::runtime_error when it stays silent for
  // `timeoutSeconds`.
  std::vector<nlohmann::json> receiveToEnd(int timeoutSeconds, int* exitStatus);

  // The end of its standard error (up to 2000 bytes), for a message.
  std::string stderrTail() const;

 private:
  [[noreturn]] void fail(const std::string& why);

  pid_t pid_ = -1;
  int socket_ = -1;     // the parent's end: the helper's stdin and stdout
  int stderrFile_ = -1;  // an unlinked temporary file
  std::string pending_;  // read but not yet returned
};

}  // namespace wg
