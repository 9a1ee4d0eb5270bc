#pragma once
// `clips serve` as a child process on 127.0.0.1, for the loopback tests: its
// stderr on a pipe, the port read from the "listening on" line and the owner
// token from the line before it; plus raw-socket helpers for requests that
// no HTTP client library would send.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <regex>
#include <string>
#include <vector>

namespace clips::serve::testing {

struct ServerProcess {
  pid_t pid = -1;
  int port = -1;
  std::string token;               // the owner token it printed
  std::vector<std::string> lines;  // stderr up to "listening on" (or to its exit)
  FILE* err = nullptr;

  // `args` after "serve --port PORT" (default: the repo's mDKG example, --max-body 1024).
  explicit ServerProcess(std::vector<std::string> extra_env = {}, std::vector<std::string> args = {},
                         int listen_port = 0) {
    if (args.empty())
      args = {"--dataset", std::string(CLIPS_SOURCE_DIR) + "/data/examples/doors-keys-gems", "--max-body", "1024"};
    const std::string bin = std::string(CLIPS_BINARY_DIR) + "/clips";
    std::vector<std::string> argv_s = {bin, "serve", "--port", std::to_string(listen_port)};
    argv_s.insert(argv_s.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : argv_s) argv.push_back(a.data());
    argv.push_back(nullptr);
    int fds[2];
    if (pipe(fds) != 0) return;
    pid = fork();
    if (pid == 0) {
      dup2(fds[1], 2);
      close(fds[0]);
      for (auto& e : extra_env) putenv(e.data());
      execv(bin.c_str(), argv.data());
      _exit(127);
    }
    close(fds[1]);
    err = fdopen(fds[0], "r");
    char line[1024];
    const std::regex re("listening on http://(?:127\\.0\\.0\\.1|\\[::1\\]):(\\d+)/");
    const std::regex tok("owner token (\\S+)");
    while (fgets(line, sizeof line, err)) {
      lines.emplace_back(line);
      std::cmatch m;
      if (std::regex_search(line, m, tok)) token = m[1];
      if (std::regex_search(line, m, re)) {
        port = std::stoi(m[1]);
        break;
      }
    }
  }
  // The exit status once the process ends by itself (128+signal when killed).
  int wait_exit() {
    int status = 0;
    waitpid(pid, &status, 0);
    pid = -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  int stop() {
    kill(pid, SIGTERM);
    return wait_exit();
  }
  std::string all_lines() const {
    std::string s;
    for (const auto& l : lines) s += l;
    return s;
  }
  ~ServerProcess() {
    if (pid > 0) {
      kill(pid, SIGKILL);
      waitpid(pid, nullptr, 0);
    }
    if (err) fclose(err);
  }
};

// A TCP connection to 127.0.0.1:port (-1 on failure); from another
// loopback address (127.0.0.2, ...) when `from` names one.
inline int connect_loopback(int port, const char* from = nullptr) {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return -1;
  if (from) {
    sockaddr_in local{};
    local.sin_family = AF_INET;
    inet_pton(AF_INET, from, &local.sin_addr);
    if (bind(fd, reinterpret_cast<sockaddr*>(&local), sizeof local) != 0) {
      close(fd);
      return -1;
    }
  }
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
    close(fd);
    return -1;
  }
  return fd;
}

inline bool send_all(int fd, const std::string& bytes) {
  size_t off = 0;
  while (off < bytes.size()) {
    const ssize_t n = send(fd, bytes.data() + off, bytes.size() - off, MSG_NOSIGNAL);
    if (n <= 0) return false;
    off += static_cast<size_t>(n);
  }
  return true;
}

// Everything the server sends until it closes, or until `seconds` pass.
inline std::string read_until_closed(int fd, double seconds) {
  std::string out;
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  char buf[4096];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - std::chrono::steady_clock::now()).count();
    if (left <= 0) break;
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, static_cast<int>(left)) <= 0) break;
    const ssize_t n = recv(fd, buf, sizeof buf, 0);
    if (n <= 0) break;
    out.append(buf, static_cast<size_t>(n));
  }
  return out;
}

// Sends raw bytes on a new connection and returns the whole reply ("" when none).
inline std::string raw_exchange(int port, const std::string& bytes, double seconds = 30) {
  const int fd = connect_loopback(port);
  if (fd < 0) return "";
  send_all(fd, bytes);
  std::string r = read_until_closed(fd, seconds);
  close(fd);
  return r;
}

// The status code of a raw reply (-1 when it has none).
inline int raw_status(const std::string& reply) {
  if (reply.compare(0, 9, "HTTP/1.1 ") != 0 || reply.size() < 12) return -1;
  return std::stoi(reply.substr(9, 3));
}

// The value of a header in a raw reply ("" when absent); the name as sent.
inline std::string raw_header(const std::string& reply, const std::string& name) {
  const size_t end = reply.find("\r\n\r\n");
  const std::string head = reply.substr(0, end);
  const std::string key = "\r\n" + name + ": ";
  const size_t at = head.find(key);
  if (at == std::string::npos) return "";
  const size_t from = at + key.size();
  return head.substr(from, head.find("\r\n", from) - from);
}

// The body of a raw reply.
inline std::string raw_body(const std::string& reply) {
  const size_t end = reply.find("\r\n\r\n");
  return end == std::string::npos ? "" : reply.substr(end + 4);
}

}  // namespace clips::serve::testing
