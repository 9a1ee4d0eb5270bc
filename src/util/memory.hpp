#pragma once
// How much more memory this process may take before the machine or its limits
// refuse it, so that work known to be too large is refused up front with the
// cause named, instead of dying of std::bad_alloc (or the OOM killer) minutes in.
#include <cstdint>
#include <optional>
#include <string>

namespace clips::util {

struct MemoryHeadroom {
  int64_t bytes = 0;  // the smallest of the sources below
  std::string bound;  // which source: "available memory", "address-space limit (ulimit -v)", "cgroup memory.max"
};

// The least of: the kernel's MemAvailable, RLIMIT_AS less the address space in
// use, and the cgroup's memory.max less memory.current. Nullopt when none of
// them can be read (then nothing is refused for memory).
std::optional<MemoryHeadroom> memory_headroom();

// The process's resident set size (from /proc/self/statm), 0 if unreadable.
int64_t resident_bytes();

// "1.5 GiB", "300 MiB": for messages.
std::string format_bytes(int64_t bytes);

}  // namespace clips::util
