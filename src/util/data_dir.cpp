#include "util/data_dir.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <algorithm>
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
// executable's when the library is shared or a Python extension).
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
  const fs::path lib = library_dir(), exe = executable_dir();
  // <prefix>/bin/clips-assist and <prefix>/lib/libclips_assist.so sit one
  // level below the prefix; a multiarch libdir (lib/x86_64-linux-gnu) two,
  // the Python package (lib/python3/dist-packages/clips_assist) four.
  auto under_prefix = [&out](const fs::path& dir) {
    if (dir.empty()) return;
    fs::path up = dir;
    for (int level = 0; level < 4 && up.has_parent_path() && up.parent_path() != up; ++level) {
      up = up.parent_path();
      out.push_back(up / "share" / "clips-assist");
    }
  };
  // The binary holding this code decides: a Python module or a shared
  // library is run by a program installed elsewhere (the interpreter in
  // /usr/bin must not lead a build tree's module to an installed package's
  // data). The pip-installed Python package carries its data beside the module.
  if (!lib.empty()) out.push_back(lib / "data");
  under_prefix(lib);
#ifdef CLIPS_SOURCE_DATA_DIR
  out.emplace_back(CLIPS_SOURCE_DATA_DIR);
#endif
  under_prefix(exe);
#ifdef CLIPS_INSTALLED_DATA_DIR
  // The installed static library, linked into a program anywhere: where it
  // was configured to install its data, then the usual prefixes.
  out.emplace_back(CLIPS_INSTALLED_DATA_DIR);
  out.emplace_back("/usr/local/share/clips-assist");
  out.emplace_back("/usr/share/clips-assist");
#endif
  // Once each, in order.
  std::vector<fs::path> unique;
  for (auto& d : out)
    if (std::find(unique.begin(), unique.end(), d) == unique.end()) unique.push_back(std::move(d));
  return unique;
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
                   "; set CLIPS_DATA_DIR to the folder holding language/, paper/ and domains/, e.g. "
                   "<prefix>/share/clips-assist)");
}

}  // namespace clips::util
