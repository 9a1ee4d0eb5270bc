// `clips serve` as a process on 127.0.0.1: the HTTP front end, its body
// limit, and SIGTERM letting an in-flight request finish before exit 0.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <regex>
#include <string>
#include <thread>

#include <httplib.h>
#include <nlohmann/json.hpp>

namespace {

using nlohmann::json;

// The server binary with its stderr on a pipe; the port is read from the
// "listening on" line.
struct ServerProcess {
  pid_t pid = -1;
  int port = -1;
  FILE* err = nullptr;

  explicit ServerProcess(std::vector<std::string> extra_env = {}) {
    int fds[2];
    if (pipe(fds) != 0) return;
    pid = fork();
    if (pid == 0) {
      dup2(fds[1], 2);
      close(fds[0]);
      for (auto& e : extra_env) putenv(e.data());
      const std::string bin = std::string(CLIPS_BINARY_DIR) + "/clips";
      const std::string ds = std::string(CLIPS_SOURCE_DIR) + "/data/examples/doors-keys-gems";
      execl(bin.c_str(), bin.c_str(), "serve", "--port", "0", "--dataset", ds.c_str(), "--max-body", "1024",
            static_cast<char*>(nullptr));
      _exit(127);
    }
    close(fds[1]);
    err = fdopen(fds[0], "r");
    char line[512];
    const std::regex re("listening on http://127\\.0\\.0\\.1:(\\d+)/");
    while (fgets(line, sizeof line, err)) {
      std::cmatch m;
      if (std::regex_search(line, m, re)) {
        port = std::stoi(m[1]);
        break;
      }
    }
  }
  int stop() {
    kill(pid, SIGTERM);
    int status = 0;
    waitpid(pid, &status, 0);
    pid = -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  ~ServerProcess() {
    if (pid > 0) {
      kill(pid, SIGKILL);
      waitpid(pid, nullptr, 0);
    }
    if (err) fclose(err);
  }
};

TEST(ServeLoopback, AnswersJsonAndLimitsBodies) {
  ServerProcess server;
  ASSERT_GT(server.port, 0);
  httplib::Client cli("127.0.0.1", server.port);
  cli.set_read_timeout(60, 0);
  auto r = cli.Get("/api/datasets");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_EQ(json::parse(r->body)["datasets"][0]["name"], "doors-keys-gems");
  r = cli.Get("/");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_NE(r->get_header_value("Content-Type").find("text/html"), std::string::npos);

  r = cli.Post("/api/sessions", json{{"dataset", "doors-keys-gems"}, {"problem", std::string(2000, 'x')}}.dump(),
               "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 413);
  EXPECT_NE(json::parse(r->body)["error"].get<std::string>().find("1024"), std::string::npos);

  r = cli.Post("/api/sessions", R"j({"dataset":"doors-keys-gems","problem":"e1"})j", "application/json");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 201);
  const std::string id = json::parse(r->body)["id"];
  r = cli.Post(("/api/sessions/" + id + "/act").c_str(), R"j({"action":"(right robot)"})j", "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 409);
  r = cli.Delete(("/api/sessions/" + id).c_str());
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_EQ(cli.Get(("/api/sessions/" + id).c_str())->status, 404);
  EXPECT_EQ(server.stop(), 0);
}

TEST(ServeLoopback, SigtermFinishesTheRequestInFlightAndExitsZero) {
  // Without the model cache the first instruction trains the embedded model
  // (about a second): a request still running when the signal comes.
  ServerProcess server({"CLIPS_LM_CACHE_DIR=off"});
  ASSERT_GT(server.port, 0);
  httplib::Client cli("127.0.0.1", server.port);
  cli.set_read_timeout(120, 0);
  auto r = cli.Post("/api/sessions", R"j({"dataset":"doors-keys-gems","problem":"e1"})j", "application/json");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 201);
  const std::string id = json::parse(r->body)["id"];
  int heard_status = -1;  // -1: no reply at all
  std::thread slow([&] {
    httplib::Client c2("127.0.0.1", server.port);
    c2.set_read_timeout(120, 0);
    auto res = c2.Post(("/api/sessions/" + id + "/hear").c_str(), R"j({"utterance":"Can you get me the yellow key?"})j",
                       "application/json");
    if (res) heard_status = res->status;
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  const auto t0 = std::chrono::steady_clock::now();
  const int code = server.stop();
  slow.join();
  EXPECT_EQ(code, 0);
  EXPECT_EQ(heard_status, 200) << "the request in flight was dropped (-1) or failed";
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 60.0);
}

}  // namespace
