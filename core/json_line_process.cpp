// A helper program spoken to in JSON lines (core/json_line_process.h). One socket pair
// carries both directions, so a write to a helper that has died fails with EPIPE
// (MSG_NOSIGNAL) instead of raising SIGPIPE in the compiler.
#include "core/json_line_process.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <thread>

#include <poll.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

namespace wg {

JsonLineProcess::JsonLineProcess(const std::vector<std::string>& argv) {
  if (argv.empty()) throw std::runtime_error("no program to start");
  // The helper's stderr goes to an unlinked file in the temporary directory (TMPDIR, else
  // /tmp when TMPDIR names nothing usable), never into the working directory.
  std::error_code ec;
  std::filesystem::path dir = std::filesystem::temp_directory_path(ec);
  if (ec || dir.empty()) dir = "/tmp";
  std::string pattern = (dir / "watergraph-helper-XXXXXX").string();
  stderrFile_ = ::mkstemp(pattern.data());
  if (stderrFile_ < 0) throw std::runtime_error("cannot make a temporary file for " + argv[0] + "'s messages");
  ::unlink(pattern.c_str());
  int pair[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, pair) != 0) {
    ::close(stderrFile_);
    throw std::runtime_error(std::string("cannot make a socket pair: ") + std::strerror(errno));
  }
  // Everything the child needs is made before fork: after it, only dup2, execv and _exit.
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_ = ::fork();
  if (pid_ < 0) {
    ::close(pair[0]);
    ::close(pair[1]);
    ::close(stderrFile_);
    throw std::runtime_error(std::string("cannot start ") + argv[0] + ": " + std::strerror(errno));
  }
  if (pid_ == 0) {
    if (::dup2(pair[1], 0) < 0 || ::dup2(pair[1], 1) < 0 || ::dup2(stderrFile_, 2) < 0) ::_exit(127);
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  ::close(pair[1]);
  socket_ = pair[0];
}

JsonLineProcess::~JsonLineProcess() {
  if (socket_ >= 0) {
    ::shutdown(socket_, SHUT_WR);  // end of input: the helper finishes and exits
  }
  if (pid_ > 0) {
    int status = 0;
    bool ended = false;
    for (int i = 0; i < 200 && !ended; ++i) {  // up to 10 s for Chromium to close
      ended = ::waitpid(pid_, &status, WNOHANG) == pid_;
      if (!ended) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    if (!ended) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, &status, 0);
    }
  }
  if (socket_ >= 0) ::close(socket_);
  if (stderrFile_ >= 0) ::close(stderrFile_);
}

std::string JsonLineProcess::stderrTail() const {
  std::string text;
  if (stderrFile_ < 0) return text;
  off_t size = ::lseek(stderrFile_, 0, SEEK_END);
  const off_t keep = 2000;
  off_t from = size > keep ? size - keep : 0;
  text.resize(static_cast<size_t>(size - from));
  ssize_t n = ::pread(stderrFile_, text.data(), text.size(), from);
  text.resize(n > 0 ? static_cast<size_t>(n) : 0);
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text;
}

void JsonLineProcess::fail(const std::string& why) {
  std::string tail = stderrTail();
  if (pid_ > 0) {  // a helper that no longer answers is ended, so the destructor does not wait on it
    ::kill(pid_, SIGKILL);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
  }
  throw std::runtime_error(why + (tail.empty() ? "" : "; its messages end: " + tail));
}

void JsonLineProcess::send(const nlohmann::json& request) {
  std::string line = request.dump() + "\n";
  size_t done = 0;
  while (done < line.size()) {
    ssize_t n = ::send(socket_, line.data() + done, line.size() - done, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail(std::string("the helper no longer reads its input (") + std::strerror(errno) + ")");
    done += static_cast<size_t>(n);
  }
}

std::vector<nlohmann::json> JsonLineProcess::receiveToEnd(int timeoutSeconds, int* exitStatus) {
  if (socket_ >= 0) ::shutdown(socket_, SHUT_WR);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeoutSeconds);
  std::vector<nlohmann::json> lines;
  for (bool open = true; open;) {
    auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
    if (left <= 0) fail("the helper did not finish within " + std::to_string(timeoutSeconds) + " s");
    pollfd p{socket_, POLLIN, 0};
    int ready = ::poll(&p, 1, static_cast<int>(left));
    if (ready <= 0) continue;
    char buf[65536];
    ssize_t n = ::recv(socket_, buf, sizeof buf, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) open = false;
    else pending_.append(buf, static_cast<size_t>(n));
  }
  pending_ += '\n';  // a last line without its newline
  for (size_t end = pending_.find('\n'); end != std::string::npos; end = pending_.find('\n')) {
    auto j = nlohmann::json::parse(pending_.substr(0, end), nullptr, false);
    pending_.erase(0, end + 1);
    if (j.is_object()) lines.push_back(std::move(j));
  }
  int status = 0;
  *exitStatus = pid_ > 0 && ::waitpid(pid_, &status, 0) == pid_ && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  pid_ = -1;
  return lines;
}

nlohmann::json JsonLineProcess::receive(int timeoutSeconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeoutSeconds);
  for (;;) {
    for (size_t end = pending_.find('\n'); end != std::string::npos; end = pending_.find('\n')) {
      std::string line = pending_.substr(0, end);
      pending_.erase(0, end + 1);
      auto j = nlohmann::json::parse(line, nullptr, false);
      if (j.is_object()) return j;
    }
    auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
    if (left <= 0) fail("the helper gave no answer within " + std::to_string(timeoutSeconds) + " s");
    pollfd p{socket_, POLLIN, 0};
    int ready = ::poll(&p, 1, static_cast<int>(left));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    char buf[65536];
    ssize_t n = ::recv(socket_, buf, sizeof buf, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail("the helper ended without an answer");
    pending_.append(buf, static_cast<size_t>(n));
  }
}

}  // namespace wg
