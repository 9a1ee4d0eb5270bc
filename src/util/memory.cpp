#include "util/memory.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace clips::util {
namespace {

// The value of a "Key:   123 kB" line of a /proc file, in bytes.
std::optional<int64_t> proc_kb(const char* path, const std::string& key) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.compare(0, key.size(), key) != 0 || line.size() <= key.size() || line[key.size()] != ':') continue;
    std::istringstream fields(line.substr(key.size() + 1));
    int64_t kb = 0;
    if (fields >> kb) return kb * 1024;
  }
  return std::nullopt;
}

std::optional<int64_t> file_number(const char* path) {
  std::ifstream in(path);
  std::string word;
  if (!(in >> word) || word == "max") return std::nullopt;
  try {
    return std::stoll(word);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace

std::optional<MemoryHeadroom> memory_headroom() {
  std::optional<MemoryHeadroom> best;
  auto consider = [&](int64_t bytes, const char* bound) {
    if (bytes < 0) bytes = 0;
    if (!best || bytes < best->bytes) best = MemoryHeadroom{bytes, bound};
  };
  if (auto avail = proc_kb("/proc/meminfo", "MemAvailable")) consider(*avail, "available memory");
  rlimit lim{};
  if (getrlimit(RLIMIT_AS, &lim) == 0 && lim.rlim_cur != RLIM_INFINITY)
    if (auto used = proc_kb("/proc/self/status", "VmSize"))
      consider(static_cast<int64_t>(lim.rlim_cur) - *used, "address-space limit (ulimit -v)");
  if (auto max = file_number("/sys/fs/cgroup/memory.max"))
    if (auto cur = file_number("/sys/fs/cgroup/memory.current")) consider(*max - *cur, "cgroup memory.max");
  return best;
}

int64_t resident_bytes() {
  std::ifstream in("/proc/self/statm");
  int64_t size = 0, resident = 0;
  if (!(in >> size >> resident)) return 0;
  return resident * static_cast<int64_t>(sysconf(_SC_PAGESIZE));
}

std::string format_bytes(int64_t bytes) {
  char buf[32];
  const double b = static_cast<double>(bytes);
  if (b >= 1024.0 * 1024 * 1024)
    std::snprintf(buf, sizeof buf, "%.1f GiB", b / (1024.0 * 1024 * 1024));
  else
    std::snprintf(buf, sizeof buf, "%.0f MiB", b / (1024.0 * 1024));
  return buf;
}

}  // namespace clips::util
