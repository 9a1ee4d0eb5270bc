#pragma once
// The project's version and the git commit the build was configured from.
// Both are compiled into one generated file (build/generated/version.cpp), so
// a new commit recompiles that file only.
#include <string>

namespace clips::util {

std::string version();     // e.g. "0.1.0", from project() in CMakeLists.txt
std::string git_commit();  // abbreviated hash, "" when unknown (no git at configure time)
// "clips 0.1.0 (commit 1234abcd)" or "clips 0.1.0" without a commit; the name
// is util::program_name() ("clips-assist 0.1.0" installed).
std::string version_line();

}  // namespace clips::util
