#pragma once
// What a shell command prints, for tests that drive the CLI.
#include <array>
#include <cstdio>
#include <string>

namespace clips::tests {

// Standard output, with standard error dropped (`with_stderr` false) or
// interleaved with it.
inline std::string command_output(const std::string& command, bool with_stderr) {
  std::string out;
  FILE* p = popen((command + (with_stderr ? " 2>&1" : " 2>/dev/null")).c_str(), "r");
  if (!p) return out;
  std::array<char, 4096> buf{};
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) out.append(buf.data(), n);
  pclose(p);
  return out;
}
inline std::string stdout_of(const std::string& command) { return command_output(command, false); }
inline std::string output_of(const std::string& command) { return command_output(command, true); }

}  // namespace clips::tests
