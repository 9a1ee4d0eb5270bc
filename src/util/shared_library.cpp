#include "util/shared_library.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <climits>

namespace clips::util {

SharedLibrary::SharedLibrary(const std::vector<std::string>& candidates, const std::string& remedy) {
  std::string reason;
  for (const auto& c : candidates) {
    // RTLD_LOCAL: its symbols serve only the lookups made through function().
    handle_ = dlopen(c.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle_ != nullptr) {
      path_ = c;
      return;
    }
    const char* e = dlerror();
    reason = e != nullptr ? e : "unknown reason";
  }
  std::string tried;
  for (const auto& c : candidates) tried += (tried.empty() ? "" : ", ") + c;
  throw SharedLibraryError("cannot load " + tried + " (" + reason + ")" + (remedy.empty() ? "" : "; " + remedy));
}

SharedLibrary::~SharedLibrary() {
  if (handle_ != nullptr) dlclose(handle_);
}

void* SharedLibrary::address(const char* name) const {
  dlerror();
  void* p = dlsym(handle_, name);
  if (p == nullptr) throw SharedLibraryError(path_ + " has no function " + name + " (too old a version?)");
  return p;
}

std::string executable_dir() {
  char buf[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0) return "";
  std::string path(buf, static_cast<size_t>(n));
  const auto slash = path.rfind('/');
  return slash == std::string::npos ? "" : path.substr(0, slash);
}

}  // namespace clips::util
