// A real `clips serve` on loopback under hostile connections: connections opened and
// left silent cannot lock other clients out (the oldest idle one is dropped
// for a new one), and ::1 cannot serve beside 127.0.0.1 on the same port
// (its URL printed with brackets).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "serve/server_process.hpp"

namespace clips::serve {
namespace {

using testing::ServerProcess;

const std::string kExamples = std::string(CLIPS_SOURCE_DIR) + "/data/examples/doors-keys-gems";

int health(int port, const char* from = nullptr) {
  const int fd = testing::connect_loopback(port, from);
  if (fd < 0) return -1;
  testing::send_all(fd, "GET /api/health HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n");
  const int status = testing::raw_status(testing::read_until_closed(fd, 20));
  close(fd);
  return status;
}

struct Idle {
  std::vector<int> fds;
  ~Idle() {
    for (int fd : fds) close(fd);
  }
};

TEST(ServeConnections, SilentConnectionsCannotLockOthersOut) {
  ServerProcess server({}, {"--dataset", kExamples, "--max-connections", "16", "--max-client-connections", "8",
                            "--read-timeout", "60"});
  ASSERT_GT(server.port, 0) << server.all_lines();
  Idle idle;
  // Eight silent connections from the honest client's own address: its
  // whole per-client share, held for the read timeout (60 s).
  for (int i = 0; i < 8; ++i) idle.fds.push_back(testing::connect_loopback(server.port));
  EXPECT_EQ(health(server.port), 200);
  // 30 more from four other addresses: the 16 in all are taken, again and again.
  for (int i = 0; i < 30; ++i) {
    const std::string from = "127.0.0." + std::to_string(2 + i % 4);
    idle.fds.push_back(testing::connect_loopback(server.port, from.c_str()));
  }
  for (int i = 0; i < 5; ++i) EXPECT_EQ(health(server.port), 200) << i;
  EXPECT_EQ(health(server.port, "127.0.0.9"), 200);
}

TEST(ServeConnections, Ipv6LoopbackBesideIpv4OnOnePortIsRefused) {
  ServerProcess v4({}, {"--dataset", kExamples});
  ASSERT_GT(v4.port, 0) << v4.all_lines();
  ServerProcess v6({}, {"--host", "::1", "--dataset", kExamples}, v4.port);
  EXPECT_EQ(v6.wait_exit(), 9) << v6.all_lines();
  EXPECT_NE(v6.all_lines().find("already in use on 127.0.0.1"), std::string::npos) << v6.all_lines();
  EXPECT_NE(v6.all_lines().find("[::1]:" + std::to_string(v4.port)), std::string::npos) << v6.all_lines();
  // On a port of its own it serves, and prints its URL with brackets.
  ServerProcess alone({}, {"--host", "::1", "--dataset", kExamples});
  EXPECT_GT(alone.port, 0) << alone.all_lines();
  EXPECT_NE(alone.all_lines().find("listening on http://[::1]:"), std::string::npos) << alone.all_lines();
  // And 127.0.0.1 cannot start beside it either.
  ServerProcess again({}, {"--dataset", kExamples}, alone.port);
  EXPECT_EQ(again.wait_exit(), 9) << again.all_lines();
  EXPECT_NE(again.all_lines().find("already in use on ::1"), std::string::npos) << again.all_lines();
}

}  // namespace
}  // namespace clips::serve
