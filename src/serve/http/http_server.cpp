// The HTTP transport of `clips serve` (cpp-httplib), built as a module of
// its own (clips-http.so) that the CLI opens only when it serves: every
// other call of the CLI starts without cpp-httplib and OpenSSL. It sees the
// service only through HttpHost (src/serve/http_server.hpp).
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <iostream>
#include <map>
#include <optional>
#include <semaphore>
#include <system_error>
#include <thread>
#include <tuple>
#include <variant>

#include <httplib.h>
#include <nlohmann/json.hpp>

#include "serve/http_guard.hpp"
#include "serve/http_server.hpp"

namespace clips::serve {

namespace {

using Clock = std::chrono::steady_clock;

// Set on a worker thread when its connection's request ran past the read
// deadline, so that the error reply says 408 rather than "malformed".
thread_local bool t_request_timed_out = false;

Reply error_json(int status, const std::string& message) {
  return Reply{status, nlohmann::json{{"error", message}, {"status", status}}.dump(), "application/json", {}};
}

// Waits until `fd` is ready for `events` or the deadline passes.
bool wait_for(int fd, short events, Clock::time_point deadline) {
  for (;;) {
    // Rounded up: false only once the deadline has passed.
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) return false;
    pollfd p{fd, events, 0};
    const int r = poll(&p, 1, static_cast<int>(std::min<long long>(left, 1000)));
    if (r > 0) return true;  // ready, or hung up / failed: the next call says which
    if (r < 0 && errno != EINTR) return false;
  }
}

std::string address_of(const sockaddr_storage& a) {
  char buf[INET6_ADDRSTRLEN] = "";
  if (a.ss_family == AF_INET) inet_ntop(AF_INET, &reinterpret_cast<const sockaddr_in&>(a).sin_addr, buf, sizeof buf);
  if (a.ss_family == AF_INET6) inet_ntop(AF_INET6, &reinterpret_cast<const sockaddr_in6&>(a).sin6_addr, buf, sizeof buf);
  return buf;
}
int port_of(const sockaddr_storage& a) {
  if (a.ss_family == AF_INET) return ntohs(reinterpret_cast<const sockaddr_in&>(a).sin_port);
  if (a.ss_family == AF_INET6) return ntohs(reinterpret_cast<const sockaddr_in6&>(a).sin6_port);
  return -1;
}

// One connection's socket for cpp-httplib: whatever was read ahead while the
// head was checked comes first; every read stops at the request's deadline,
// every write at the reply's (set at its first byte).
class ConnectionStream : public httplib::Stream {
 public:
  ConnectionStream(int fd, Clock::time_point read_deadline, Clock::duration write_time)
      : fd_(fd), read_deadline_(read_deadline), write_time_(write_time) {}

  bool is_readable() const override { return pos_ < ahead_.size() || wait_for(fd_, POLLIN, read_deadline_); }
  bool is_writable() const override { return wait_for(fd_, POLLOUT, write_deadline()); }

  ssize_t read(char* ptr, size_t size) override {
    if (pos_ < ahead_.size()) {
      const size_t n = std::min(size, ahead_.size() - pos_);
      std::memcpy(ptr, ahead_.data() + pos_, n);
      pos_ += n;
      return static_cast<ssize_t>(n);
    }
    return receive(ptr, size);
  }
  ssize_t write(const char* ptr, size_t size) override {
    if (!writing_) {
      writing_ = true;
      write_deadline_ = Clock::now() + write_time_;
    }
    if (!wait_for(fd_, POLLOUT, write_deadline_)) return -1;
    ssize_t n;
    do n = ::send(fd_, ptr, size, MSG_NOSIGNAL);
    while (n < 0 && errno == EINTR);
    return n;
  }
  void get_remote_ip_and_port(std::string& ip, int& port) const override {
    sockaddr_storage a{};
    socklen_t len = sizeof a;
    if (getpeername(fd_, reinterpret_cast<sockaddr*>(&a), &len) == 0) {
      ip = address_of(a);
      port = port_of(a);
    }
  }
  void get_local_ip_and_port(std::string& ip, int& port) const override {
    sockaddr_storage a{};
    socklen_t len = sizeof a;
    if (getsockname(fd_, reinterpret_cast<sockaddr*>(&a), &len) == 0) {
      ip = address_of(a);
      port = port_of(a);
    }
  }
  socket_t socket() const override { return fd_; }

  // Reads what has arrived (at most `max` more bytes) into the read-ahead;
  // false at end of stream, on an error or past the deadline.
  bool read_ahead(size_t max) {
    char buf[4096];
    const ssize_t n = receive(buf, std::min(max, sizeof buf));
    if (n <= 0) return false;
    ahead_.append(buf, static_cast<size_t>(n));
    return true;
  }
  std::string_view ahead() const { return ahead_; }
  bool past_deadline() const { return Clock::now() >= read_deadline_; }
  // Waits until bytes (or the end of the stream) can be read, up to the deadline.
  bool readable() const { return wait_for(fd_, POLLIN, read_deadline_); }

 private:
  ssize_t receive(char* ptr, size_t size) {
    if (!wait_for(fd_, POLLIN, read_deadline_)) {
      t_request_timed_out = Clock::now() >= read_deadline_;
      return -1;
    }
    ssize_t n;
    do n = ::recv(fd_, ptr, size, 0);
    while (n < 0 && errno == EINTR);
    return n;
  }
  Clock::time_point write_deadline() const { return writing_ ? write_deadline_ : Clock::now() + write_time_; }

  int fd_;
  Clock::time_point read_deadline_;
  Clock::duration write_time_;
  bool writing_ = false;
  Clock::time_point write_deadline_{};
  std::string ahead_;
  size_t pos_ = 0;
};

// Writes a whole reply, closes the sending side and reads (and drops) what
// the client still sends for up to `linger`, so that the reply is not lost
// to a reset when unread request bytes remain; then closes.
void reply_and_close(int fd, const std::string& response, Clock::duration linger) {
  const auto deadline = Clock::now() + std::chrono::seconds(5);
  size_t off = 0;
  while (off < response.size() && wait_for(fd, POLLOUT, deadline)) {
    const ssize_t n = ::send(fd, response.data() + off, response.size() - off, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    off += static_cast<size_t>(n);
  }
  ::shutdown(fd, SHUT_WR);
  const auto until = Clock::now() + linger;
  char buf[4096];
  size_t drained = 0;
  while (drained < (1u << 20) && wait_for(fd, POLLIN, until)) {
    const ssize_t n = ::recv(fd, buf, sizeof buf, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    drained += static_cast<size_t>(n);
  }
  ::close(fd);
}

// Worker threads made as connections need them, up to a bound, and kept.
// A connection over the limits is answered 503 at once, so a worker is
// always free soon for the next one.
class ConnectionPool : public httplib::TaskQueue {
 public:
  explicit ConnectionPool(size_t max_threads) : max_(max_threads) {}
  ~ConnectionPool() override = default;

  void enqueue(std::function<void()> fn) override {
    {
      std::lock_guard lock(m_);
      jobs_.push_back(std::move(fn));
      if (jobs_.size() > idle_ && threads_.size() < max_) {
        try {
          threads_.emplace_back([this] { work(); });
        } catch (const std::system_error&) {
          // No new thread: the job waits for a worker that exists, or, when
          // there is none, runs here on the accepting thread.
          if (threads_.empty()) {
            fn = std::move(jobs_.back());
            jobs_.pop_back();
          }
        }
      }
    }
    cv_.notify_one();
    if (fn) fn();
  }
  void shutdown() override {
    {
      std::lock_guard lock(m_);
      stop_ = true;
    }
    cv_.notify_all();
    for (auto& t : threads_) t.join();
  }

 private:
  void work() {
    for (;;) {
      std::function<void()> fn;
      {
        std::unique_lock lock(m_);
        while (!stop_ && jobs_.empty()) {
          ++idle_;
          cv_.wait(lock);
          --idle_;
        }
        if (jobs_.empty()) return;
        fn = std::move(jobs_.front());
        jobs_.pop_front();
      }
      fn();
    }
  }
  const size_t max_;
  std::mutex m_;
  std::condition_variable cv_;
  std::deque<std::function<void()>> jobs_;
  std::vector<std::thread> threads_;
  size_t idle_ = 0;
  bool stop_ = false;
};

// Open connections, in all and per client address. A connection is idle
// until its request head has arrived; when a new connection finds the table
// full, an idle connection is dropped for it (of the same client, when that
// client is at its own limit), so that connections opened and left silent
// cannot lock others out: a silent one first (nothing received, nothing
// waiting), of the client holding the most idle connections (a player has
// one at most, for a moment), the oldest among equals.
class ConnectionTable {
 public:
  ConnectionTable(int max_total, int max_per_client) : max_total_(max_total), max_per_client_(max_per_client) {}

  // A slot for the connection on `fd` (its id), or why it is refused.
  std::variant<uint64_t, std::string> take(int fd, const std::string& client) {
    std::lock_guard lock(m_);
    const auto mine = per_client_.find(client);
    if (mine != per_client_.end() && mine->second >= max_per_client_ && !drop_oldest_idle_locked(&client))
      return std::to_string(max_per_client_) + " connections from " + client +
             " are open and busy (--max-client-connections); try again";
    if (total_ >= max_total_ && !drop_oldest_idle_locked(nullptr))
      return std::to_string(max_total_) + " connections are open and busy (--max-connections); try again";
    ++per_client_[client];
    ++total_;
    const uint64_t id = next_id_++;
    open_[id] = Conn{fd, client, Clock::now(), true, false, false};
    return id;
  }
  // Its first bytes have arrived: not silent.
  void heard(uint64_t id) {
    std::lock_guard lock(m_);
    if (auto it = open_.find(id); it != open_.end()) it->second.heard = true;
  }
  // Its request head has arrived (or it ended): no longer a connection to drop.
  // Called before the connection's socket is closed.
  void settled(uint64_t id) {
    std::lock_guard lock(m_);
    if (auto it = open_.find(id); it != open_.end()) it->second.idle = false;
  }
  void give_back(uint64_t id) {
    std::lock_guard lock(m_);
    auto it = open_.find(id);
    if (it == open_.end()) return;
    if (!it->second.dropped) release_locked(it->second.client);
    open_.erase(it);
  }
  // Connections dropped for newer ones so far (for the log).
  uint64_t dropped() const {
    std::lock_guard lock(m_);
    return dropped_;
  }

 private:
  struct Conn {
    int fd;
    std::string client;
    Clock::time_point since;
    bool idle, dropped, heard;
  };
  // Nothing received from it, and nothing waiting to be read.
  static bool silent(const Conn& c) {
    int waiting = 0;
    return !c.heard && ::ioctl(c.fd, FIONREAD, &waiting) == 0 && waiting == 0;
  }
  void release_locked(const std::string& client) {
    --total_;
    if (--per_client_[client] <= 0) per_client_.erase(client);
  }
  // Shuts the oldest idle connection down (of `client`, or of the client
  // holding the most connections) and hands its slot over; false when there
  // is none. Its thread sees the end of the stream and closes it; the socket
  // is still open here, since a connection settles before it is closed.
  bool drop_oldest_idle_locked(const std::string* client) {
    std::map<std::string, int> idle_of;  // idle connections per client
    for (const auto& [id, c] : open_)
      if (c.idle && !c.dropped) ++idle_of[c.client];
    Conn* victim = nullptr;
    bool victim_silent = false;
    for (auto& [id, c] : open_) {
      if (!c.idle || c.dropped || (client && c.client != *client)) continue;
      const bool quiet = silent(c);
      const auto rank = std::tuple(quiet, idle_of[c.client], Clock::time_point::max() - c.since);
      if (!victim || rank > std::tuple(victim_silent, idle_of[victim->client], Clock::time_point::max() - victim->since)) {
        victim = &c;
        victim_silent = quiet;
      }
    }
    if (!victim) return false;
    ::shutdown(victim->fd, SHUT_RDWR);
    victim->dropped = true;
    release_locked(victim->client);
    ++dropped_;
    return true;
  }

  mutable std::mutex m_;
  const int max_total_, max_per_client_;
  int total_ = 0;
  uint64_t next_id_ = 1, dropped_ = 0;
  std::map<std::string, int> per_client_;
  std::map<uint64_t, Conn> open_;
};

class GuardedServer : public httplib::Server {
 public:
  GuardedServer(const HttpOptions& options, GuardPolicy policy)
      : policy_(std::move(policy)),
        read_time_(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.read_timeout))),
        table_(options.max_connections, options.max_client_connections) {}

  // The listening socket once bound (to raise its backlog).
  int listening_socket() const { return svr_sock_; }

 private:
  bool process_and_close_socket(socket_t sock) override {
    const auto start = Clock::now();
    sockaddr_storage peer{};
    socklen_t len = sizeof peer;
    const std::string client = getpeername(sock, reinterpret_cast<sockaddr*>(&peer), &len) == 0 ? address_of(peer) : "";
    const auto taken = table_.take(sock, client);
    if (const auto* full = std::get_if<std::string>(&taken)) {
      Reply r = error_json(503, "the server is busy: " + *full);
      r.headers.emplace_back("Retry-After", "1");
      reply_and_close(sock, format_response(r), std::chrono::milliseconds(100));
      return true;
    }
    struct Slot {
      ConnectionTable& table;
      uint64_t id;
      ~Slot() { table.give_back(id); }
    } slot{table_, std::get<uint64_t>(taken)};

    t_request_timed_out = false;
    ConnectionStream strm(sock, start + read_time_, read_time_);
    RequestHead head;
    size_t head_bytes = 0;
    HeadScan scan;
    bool heard = false;
    while ((scan = scan_head(strm.ahead(), head, head_bytes)) == HeadScan::incomplete) {
      // Said heard while its first bytes still wait in the socket, so that
      // it never looks silent to a newcomer.
      if (!heard && strm.readable()) {
        table_.heard(slot.id);
        heard = true;
      }
      if (!strm.read_ahead(kMaxHead + 1 - std::min(kMaxHead, strm.ahead().size()))) break;
    }
    table_.settled(slot.id);  // from here on it is not dropped for others (and may be closed)
    std::optional<Reply> reject;
    switch (scan) {
      case HeadScan::incomplete:
        if (strm.past_deadline() && !strm.ahead().empty())
          reject = error_json(408, "the request did not arrive within the read timeout");
        break;
      case HeadScan::request_line_too_long:
        reject = error_json(414, "request line longer than " + std::to_string(kMaxRequestLine) + " bytes");
        break;
      case HeadScan::too_large:
        reject = error_json(431, "request headers longer than " + std::to_string(kMaxHeaderLine) + " bytes a line or " +
                                     std::to_string(kMaxHead) + " in all");
        break;
      case HeadScan::malformed:
        reject = error_json(400, "malformed request line or header");
        break;
      case HeadScan::complete:
        reject = screen_request(head, policy_);
        break;
    }
    if (reject || scan != HeadScan::complete) {
      if (reject) reply_and_close(sock, format_response(*reject, head.method == "HEAD"), std::chrono::seconds(1));
      else ::close(sock);
      return true;
    }
    bool closed = false;
    process_request(strm, true, closed, [](httplib::Request&) {});
    ::shutdown(sock, SHUT_RDWR);
    ::close(sock);
    return true;
  }

  GuardPolicy policy_;
  Clock::duration read_time_;
  ConnectionTable table_;
};

// Whether `port` on the other loopback address (::1 for 127.0.0.1 and back)
// is taken by a listening socket: "localhost:PORT" would then reach two
// servers, whichever the client's resolver tries first.
bool sibling_loopback_taken(const std::string& host, int port) {
  const bool v4 = host == "127.0.0.1", v6 = host == "::1";
  if (!v4 && !v6) return false;
  const int family = v4 ? AF_INET6 : AF_INET;
  const int fd = ::socket(family, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return false;  // no such family here: nothing to share the name with
  int yes = 1;
  setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);  // as the server binds: only a listener conflicts
  if (family == AF_INET6) setsockopt(fd, IPPROTO_IPV6, IPV6_V6ONLY, &yes, sizeof yes);
  sockaddr_storage a{};
  socklen_t len = 0;
  if (family == AF_INET) {
    auto& in = reinterpret_cast<sockaddr_in&>(a);
    in.sin_family = AF_INET;
    in.sin_port = htons(static_cast<uint16_t>(port));
    in.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    len = sizeof in;
  } else {
    auto& in6 = reinterpret_cast<sockaddr_in6&>(a);
    in6.sin6_family = AF_INET6;
    in6.sin6_port = htons(static_cast<uint16_t>(port));
    in6.sin6_addr = in6addr_loopback;
    len = sizeof in6;
  }
  const bool taken = ::bind(fd, reinterpret_cast<sockaddr*>(&a), len) != 0 && errno == EADDRINUSE;
  ::close(fd);
  return taken;
}

// "host:port" for a URL: an IPv6 literal in brackets.
std::string url_authority(const std::string& host, int port) {
  const bool v6 = host.find(':') != std::string::npos && host.front() != '[';
  return (v6 ? "[" + host + "]" : host) + ":" + std::to_string(port);
}

bool same_token(const std::string& given, const std::string& token) {
  if (token.empty() || given.size() != token.size()) return false;
  unsigned char diff = 0;
  for (size_t i = 0; i < token.size(); ++i) diff |= static_cast<unsigned char>(given[i] ^ token[i]);
  return diff == 0;
}

}  // namespace

int run_http_server(const HttpHost& host, const HttpOptions& options, std::ostream& log) {
  // Signals are taken by one thread with sigwait, never by a handler, so
  // stopping is an ordinary call made outside any request.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

  GuardPolicy policy;
  policy.listen_host = options.host;
  policy.allow_origins = options.allow_origins;
  policy.max_body_bytes = host.max_body_bytes;
  policy.allowed_methods = host.allowed_methods;
  GuardedServer server(options, policy);
  // Workers for every connection allowed, and a few to turn away the rest.
  const size_t workers = static_cast<size_t>(options.max_connections) + 4;
  server.new_task_queue = [workers] { return new ConnectionPool(workers); };
  // SO_REUSEADDR only (cpp-httplib also sets SO_REUSEPORT, which let a second
  // server share a port that is in use).
  server.set_socket_options([](socket_t sock) {
    int yes = 1;
    setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });
  server.set_payload_max_length(host.max_body_bytes);
  server.set_keep_alive_max_count(1);  // one request a connection: each is checked before it is read
  std::counting_semaphore<> working(std::max(1, options.threads));
  auto serve = [&host, &options, &policy, &working](const httplib::Request& req, httplib::Response& res) {
    Request request{req.method, req.path, req.body, false, req.remote_addr};
    const std::string auth = req.get_header_value("Authorization");
    request.owner = auth.compare(0, 7, "Bearer ") == 0 && same_token(auth.substr(7), options.owner_token);
    // Session requests compute: at most --threads at once. The rest is cheap
    // and never waits behind them.
    const bool heavy = req.path.compare(0, 14, "/api/sessions/") == 0 || req.path == "/api/sessions";
    if (heavy) working.acquire();
    Reply r;
    try {
      r = host.handle(request);
    } catch (...) {
      if (heavy) working.release();
      throw;
    }
    if (heavy) working.release();
    res.status = r.status;
    for (const auto& [name, value] : r.headers) res.set_header(name.c_str(), value.c_str());
    RequestHead head;
    if (req.has_header("Origin")) head.headers.emplace_back("origin", req.get_header_value("Origin"));
    if (req.has_header("Host")) head.headers.emplace_back("host", req.get_header_value("Host"));
    if (check_origin(head, policy) == OriginVerdict::allowed_cross) {
      res.set_header("Access-Control-Allow-Origin", req.get_header_value("Origin").c_str());
      res.set_header("Vary", "Origin");
    }
    res.set_content(r.body, r.content_type.c_str());
  };
  const std::string any = R"(/.*)";
  server.Get(any, serve);
  server.Post(any, serve);
  server.Delete(any, serve);
  server.set_error_handler([&host](const httplib::Request&, httplib::Response& res) {
    if (!res.body.empty()) return;
    if (t_request_timed_out) res.status = 408;  // the body did not arrive in time
    std::string msg;
    switch (res.status) {
      case 408: msg = "the request did not arrive within the read timeout (--read-timeout)"; break;
      case 413:
        msg = "request body exceeds the limit of " + std::to_string(host.max_body_bytes) + " bytes (--max-body)";
        break;
      case 400: msg = "malformed request"; break;
      default: msg = "request failed";
    }
    res.set_content(nlohmann::json{{"error", msg}, {"status", res.status}}.dump(), "application/json");
  });

  int port = options.port;
  errno = 0;
  if (port == 0) port = server.bind_to_any_port(options.host);
  else if (!server.bind_to_port(options.host, port)) port = -1;
  if (port < 0) {
    const int err = errno;
    log << host.program_name << " serve: error: cannot listen on " << url_authority(options.host, options.port) << ": "
        << (err == EADDRINUSE ? "the port is already in use (is another " + host.program_name + " serve running?)"
                              : err ? std::strerror(err) : "the address cannot be bound")
        << "\n"
        << std::flush;
    return kCannotListen;
  }
  if (sibling_loopback_taken(options.host, port)) {
    log << "clips serve: error: cannot listen on " << url_authority(options.host, port) << ": the port is already in use on "
        << (options.host == "::1" ? "127.0.0.1" : "::1")
        << ", so localhost:" << port << " would reach two servers (is another clips serve running?)\n"
        << std::flush;
    return kCannotListen;
  }
  ::listen(server.listening_socket(), kListenBacklog);  // again, with the larger backlog

  std::mutex m;
  std::condition_variable cv;
  bool done = false;
  std::thread stopper([&] {
    int sig = 0;
    sigwait(&stop_signals, &sig);
    {
      std::lock_guard lock(m);
      done = true;
    }
    cv.notify_all();
    server.stop();
  });
  std::thread sweeper([&] {  // idle sessions go even when no request comes
    std::unique_lock lock(m);
    while (!cv.wait_for(lock, std::chrono::seconds(1), [&] { return done; })) {
      lock.unlock();
      host.expire_idle();
      lock.lock();
    }
  });

  if (options.host != "127.0.0.1" && options.host != "localhost" && options.host != "::1")
    log << host.program_name << " serve: note: listening on " << options.host << ", not loopback only: anyone who can reach it may use it\n";
  if (!options.owner_token.empty())
    log << host.program_name << " serve: owner token " << options.owner_token
        << " (GET or DELETE /api/sessions with the header 'Authorization: Bearer TOKEN' lists or deletes every session)\n";
  log << host.program_name << " serve: listening on http://" << url_authority(options.host, port) << "/\n" << std::flush;
  server.listen_after_bind();  // returns after stop(), once in-flight requests are answered

  // listen_after_bind can also end on its own (socket error): wake the stopper.
  {
    std::lock_guard lock(m);
    if (!done) pthread_kill(stopper.native_handle(), SIGTERM);
  }
  stopper.join();
  sweeper.join();
  log << host.program_name << " serve: stopped\n" << std::flush;
  return 0;
}

}  // namespace clips::serve

// The one symbol the module exports (it is built with hidden visibility).
extern "C" __attribute__((visibility("default"))) int clips_http_serve(const clips::serve::HttpHost& host, const clips::serve::HttpOptions& options,
                                std::ostream& log) {
  return clips::serve::run_http_server(host, options, log);
}
