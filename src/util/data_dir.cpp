#include "util/data_dir.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <vector>

#include "util/error.hpp"

namespace clips::util {
namespace {

namespace fs = std::filesystem;

// The folder of the running executable, or "" when /proc is unavailable.
fs::path executable_dir() {
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe.parent_path();
}

// The folder of the binary this function was linked into (differs from the
// executable's when clips is a shared library or a Python extension).
fs::path library_dir() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&library_dir), &info) == 0 || info.dli_fname == nullptr) return {};
  std::error_code ec;
  fs::path p = fs::canonical(info.dli_fname, ec);
  return ec ? fs::path() : p.parent_path();
}

std::vector<fs::path> candidates() {
  std::vector<fs::path> out;
  if (const char* env = std::getenv("CLIPS_DATA_DIR"); env != nullptr && *env != '\0') {
    out.emplace_back(env);
    return out;  // an explicit choice is never second-guessed
  }
  // <prefix>/bin/clips and <prefix>/lib/libclips.so sit one level below the
  // prefix; a multiarch libdir (lib/x86_64-linux-gnu) two, the Python module
  // (lib/python3/dist-packages) three.
  for (const fs::path& dir : {executable_dir(), library_dir()}) {
    if (dir.empty()) continue;
    fs::path up = dir;
    for (int level = 0; level < 3 && up.has_parent_path() && up.parent_path() != up; ++level) {
      up = up.parent_path();
      out.push_back(up / "share" / "clips");
    }
  }
#ifdef CLIPS_SOURCE_DATA_DIR
  out.emplace_back(CLIPS_SOURCE_DATA_DIR);
#endif
  return out;
}

}  // namespace

std::string data_dir() {
  const auto dirs = candidates();
  for (const auto& d : dirs) {
    std::error_code ec;
    if (fs::is_directory(d / "language", ec)) return d.string();
  }
  return dirs.empty() ? std::string("data") : dirs.front().string();
}

std::string data_path(const std::string& relative) {
  std::string searched;
  for (const auto& d : candidates()) {
    std::error_code ec;
    if (fs::exists(d / relative, ec)) return (d / relative).string();
    searched += (searched.empty() ? "" : ", ") + d.string();
  }
  throw InputError("data file '" + relative + "' not found (searched " + searched +
                   "; set CLIPS_DATA_DIR to the folder holding language/, paper/ and domains/)");
}

}  // namespace clips::util
