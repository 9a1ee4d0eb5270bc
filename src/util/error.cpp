#include "util/error.hpp"

namespace clips {

std::string SourceLoc::str() const {
  std::string s = file.empty() ? "<input>" : file;
  if (line > 0) {
    s += ":" + std::to_string(line);
    if (col > 0) s += ":" + std::to_string(col);
  }
  return s;
}

InputError::InputError(const SourceLoc& loc, const std::string& what)
    : std::runtime_error(loc.str() + ": " + what) {}

}  // namespace clips
