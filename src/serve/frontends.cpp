#include "serve/frontends.hpp"

#include <pthread.h>
#include <signal.h>

#include <condition_variable>
#include <iostream>
#include <thread>

#include <httplib.h>
#include <nlohmann/json.hpp>

namespace clips::serve {

int run_http(Service& service, const HttpOptions& options, std::ostream& log) {
  // Signals are taken by one thread with sigwait, never by a handler, so
  // stopping is an ordinary call made outside any request.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

  httplib::Server server;
  const int threads = options.threads;
  server.new_task_queue = [threads] { return new httplib::ThreadPool(static_cast<size_t>(threads)); };
  // httplib refuses larger bodies before reading them (413); the service
  // checks again so that the JSON-lines mode has the same limit.
  server.set_payload_max_length(service.limits().max_body_bytes);
  server.set_read_timeout(10, 0);
  server.set_write_timeout(10, 0);
  auto serve = [&service](const httplib::Request& req, httplib::Response& res) {
    Reply r = service.handle(req.method, req.path, req.body);
    res.status = r.status;
    res.set_content(r.body, r.content_type.c_str());
  };
  const std::string any = R"(/.*)";
  server.Get(any, serve);
  server.Post(any, serve);
  server.Delete(any, serve);
  server.set_error_handler([&service](const httplib::Request&, httplib::Response& res) {
    if (!res.body.empty()) return;
    std::string msg = res.status == 413 ? "request body exceeds the limit of " +
                                              std::to_string(service.limits().max_body_bytes) + " bytes"
                                        : "request failed";
    res.set_content(nlohmann::json{{"error", msg}, {"status", res.status}}.dump(), "application/json");
  });

  int port = options.port;
  if (port == 0) port = server.bind_to_any_port(options.host);
  else if (!server.bind_to_port(options.host, port)) port = -1;
  if (port < 0) {
    log << "clips serve: error: cannot listen on " << options.host << ":" << options.port << "\n" << std::flush;
    return 1;
  }

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
      service.expire_idle();
      lock.lock();
    }
  });

  if (options.host != "127.0.0.1" && options.host != "localhost" && options.host != "::1")
    log << "clips serve: note: listening on " << options.host << ", not loopback only: anyone who can reach it may use it\n";
  log << "clips serve: listening on http://" << options.host << ":" << port << "/\n" << std::flush;
  server.listen_after_bind();  // returns after stop(), once in-flight requests are answered

  // listen_after_bind can also end on its own (socket error): wake the stopper.
  {
    std::lock_guard lock(m);
    if (!done) pthread_kill(stopper.native_handle(), SIGTERM);
  }
  stopper.join();
  sweeper.join();
  log << "clips serve: stopped\n" << std::flush;
  return 0;
}

int run_stdio(Service& service, std::istream& in, std::ostream& out) {
  using nlohmann::json;
  std::string line;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    json reply;
    try {
      const json req = json::parse(line);
      if (!req.is_object()) throw std::runtime_error("request: expected a JSON object");
      for (auto it = req.begin(); it != req.end(); ++it)
        if (it.key() != "method" && it.key() != "path" && it.key() != "body")
          throw std::runtime_error("unknown field '" + it.key() + "' (allowed: body, method, path)");
      if (!req.contains("method") || !req["method"].is_string()) throw std::runtime_error("field 'method': expected a string");
      if (!req.contains("path") || !req["path"].is_string()) throw std::runtime_error("field 'path': expected a string");
      const std::string body = req.contains("body") ? req["body"].dump() : "";
      Reply r = service.handle(req["method"].get<std::string>(), req["path"].get<std::string>(), body);
      reply["status"] = r.status;
      reply["body"] = r.content_type == "application/json" ? json::parse(r.body) : json(r.body);
    } catch (const std::exception& e) {
      reply = {{"status", 400}, {"body", {{"error", std::string("malformed request line: ") + e.what()}, {"status", 400}}}};
    }
    out << reply.dump(-1, ' ', false, json::error_handler_t::replace) << "\n" << std::flush;
  }
  return 0;
}

}  // namespace clips::serve
