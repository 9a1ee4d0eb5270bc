#pragma once
// A shared library opened when first needed (dlopen) rather than at start-up.
// The optional parts of the program (the LM client's libcurl, the web
// server) pull in dozens of libraries that the dynamic loader would map and
// initialise on every call of the CLI, most of which never uses them.
#include <stdexcept>
#include <string>
#include <vector>

namespace clips::util {

class SharedLibraryError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class SharedLibrary {
 public:
  // Opens the first of `candidates` (sonames or paths) that loads; throws
  // SharedLibraryError naming every candidate, the loader's last reason and
  // `remedy` (for example the package to install) when none does.
  SharedLibrary(const std::vector<std::string>& candidates, const std::string& remedy);
  ~SharedLibrary();
  SharedLibrary(const SharedLibrary&) = delete;
  SharedLibrary& operator=(const SharedLibrary&) = delete;

  // The function `name` as type F (a function pointer); throws
  // SharedLibraryError when the library does not define it.
  template <class F>
  F function(const char* name) const {
    return reinterpret_cast<F>(address(name));
  }
  const std::string& path() const { return path_; }

 private:
  void* address(const char* name) const;
  void* handle_ = nullptr;
  std::string path_;
};

// The directory of the running executable (/proc/self/exe), "" when unknown.
std::string executable_dir();

}  // namespace clips::util
