#include "util/program_name.hpp"

namespace clips::util {

namespace {
std::string& name() {
  static std::string n = "clips";
  return n;
}
}  // namespace

const std::string& program_name() { return name(); }

void set_program_name(const char* argv0) {
  if (argv0 == nullptr) return;
  std::string path = argv0;
  const auto slash = path.find_last_of('/');
  if (slash != std::string::npos) path = path.substr(slash + 1);
  if (!path.empty()) name() = path;
}

}  // namespace clips::util
